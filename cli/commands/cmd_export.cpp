// `fapcast export IN -o OUT.bvh|OUT.json [--sample-rate HZ]`: a FAP track (.fap text or fapcast
// JSON) as a BVH skeleton animation (spec/bvh.md) or as JSON for web players (spec/json.md).
// The output format follows OUT's extension. Argument parsing only; the codec does the work.
#include "command.hpp"
#include "output_check.hpp"

#include "fapcast/codec/bvh_export.hpp"
#include "fapcast/codec/bvh_text.hpp"
#include "fapcast/codec/fap_text.hpp"
#include "fapcast/codec/json_export.hpp"
#include "fapcast/core/file_io.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace {
using namespace fapcast;

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The input track and, for JSON input, what its header said (FAPU pass through).
FapJsonRead read_track(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == ".fap") {
    FapTextRead r = read_fap_text(read_file(path), path);
    for (const auto& w : r.info.warnings) std::cerr << "fapcast: warning: " << w << "\n";
    return {std::move(r.sequence), {}};
  }
  if (ext == ".json") return read_fap_json(read_file(path), path);
  throw cli::UsageError("export: input '" + path + "' is neither .fap nor .json");
}

const cli::Registration export_command{"export", [](CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "export", "Export a FAP track (.fap or .json) as BVH (head, jaw, tongue-tip and lip joints "
                "on a generic adult face, cm) or as JSON for web players");
  auto in = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto sample_rate = std::make_shared<std::int64_t>(0);
  cmd->add_option("IN", *in, "input track: .fap text or fapcast .json")->required();
  cmd->add_option("-o,--output", *out, "output file: .bvh or .json (written atomically)")
      ->required();
  auto* rate_opt = cmd->add_option("--sample-rate", *sample_rate,
                                   "JSON only: add each frame's WAV sample position at HZ")
                       ->check(CLI::Range(std::int64_t{1}, kFapJsonMaxRate));
  cmd->callback([=] {
    const std::string ext = extension_of(*out);
    if (ext != ".bvh" && ext != ".json")
      throw cli::UsageError("export: output '" + *out + "' must end in .bvh or .json");
    if (ext == ".bvh" && rate_opt->count() > 0)
      throw cli::UsageError("export: --sample-rate applies to .json output only");
    cli::check_output_writable(*out);
    FapJsonRead track = read_track(*in);
    std::string bytes;
    if (ext == ".bvh") {
      bytes = write_bvh(fap_to_bvh(track.sequence, generic_adult_face()));
    } else {
      FapJsonOptions options = track.options;
      options.generator = std::string("fapcast ") + FAPCAST_VERSION;
      if (rate_opt->count() > 0) options.sample_rate = SampleRate{*sample_rate};
      bytes = write_fap_json(track.sequence, options);
    }
    write_file_atomically(*out, bytes);
    std::cout << "export: " << track.sequence.frames.size() << " frames at "
              << track.sequence.rate << " -> " << *out << "\n";
  });
}};

}  // namespace
