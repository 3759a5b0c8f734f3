// `fapcast corpus record-reference`: records the SYNTHETIC reference corpus (spec/corpus.md).
#include "command.hpp"
#include "recording_script_options.hpp"

#include "fapcast/talker/reference_talker.hpp"
#include "fapcast/core/file_io.hpp"

#include <chrono>
#include <iostream>
#include <memory>

namespace {

const fapcast::cli::Registration corpus_record_command{"corpus record-reference", [](CLI::App& app) {
  struct Args {
    std::string output;
    fapcast::ReferenceCorpusOptions options;
    fapcast::cli::RecordingScriptInputs inputs;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = fapcast::cli::command_group(app, "corpus", fapcast::cli::kCorpusGroupHelp)
                  ->add_subcommand("record-reference",
                                   "Record the SYNTHETIC reference corpus: per script item a C3D of "
                                   "the face markers (60 fps), the espeak-ng WAV and a TextGrid; "
                                   "plus manifest.json");
  cmd->add_option("-o,--output", args->output, "Corpus directory (created)")->required();
  cmd->add_option("--count", args->options.count, "Record only the first N script items (0 = all)")
      ->capture_default_str();
  cmd->add_option("--seed", args->options.seed, "Seed of the actor, variations and imperfections")
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", args->quiet, "No progress on standard error");
  fapcast::cli::add_recording_script_options(cmd, args->inputs);
  cmd->callback([args] {
    namespace fs = std::filesystem;
    const auto script = fapcast::cli::load_recording_script(args->inputs);
    const fs::path dir = args->output;
    const auto start = std::chrono::steady_clock::now();
    const auto summary = fapcast::record_reference_corpus(
        script, dir, args->options,
        [&](const std::string& name, std::string_view bytes) {
          fapcast::write_file_atomically(dir / name, bytes);
        },
        [&](std::size_t done, std::size_t total) {
          if (!args->quiet && (done % 50 == 0 || done == total))
            std::cerr << "\rrecorded " << done << " / " << total << std::flush;
        });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!args->quiet) std::cerr << "\n";
    std::cout << "SYNTHETIC reference corpus in " << dir.string() << ": " << summary.utterances
              << " utterances, " << summary.audio_seconds << " s of audio, " << summary.marker_frames
              << " marker frames at 60 fps, " << summary.bytes << " bytes, recorded in " << seconds
              << " s\n";
    std::cout << "divisemes recorded: " << summary.divisemes_recorded << " of " << fapcast::kDivisemeCount << "\n";
    if (!summary.divisemes_not_said.empty()) {
      std::string names;
      for (std::uint32_t d : summary.divisemes_not_said) names += " " + fapcast::diviseme_name(d);
      std::cerr << "fapcast: warning: " << summary.divisemes_not_said.size()
                << " diviseme(s) of the script's pronunciations are in no take (espeak-ng said the items "
                   "otherwise; the unit search joins anywhere for them):"
                << names << "\n";
    }
  });
}};

}  // namespace
