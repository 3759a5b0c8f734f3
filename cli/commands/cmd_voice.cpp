// `fapcast voice build`, `voice info`, `voice default` (spec/voice.md) and `voice adapt`
// (spec/adaptation.md).
#include "command.hpp"
#include "output_check.hpp"
#include "default_voice.hpp"

#include "fapcast/core/synthetic_label.hpp"
#include "fapcast/voice/voice.hpp"
#include "fapcast/face/obj_mesh.hpp"
#include "fapcast/builder/voice_build.hpp"
#include "fapcast/voice/voice_adaptation.hpp"
#include "fapcast/core/file_io.hpp"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <stdexcept>

#ifndef FAPCAST_VERSION
#define FAPCAST_VERSION "unknown"
#endif

namespace {

constexpr const char* kVoiceGroupHelp = "Build a voice from a capture corpus; show what a voice holds";

std::string_view element_type_name(fapcast::ElementType type) {
  using fapcast::ElementType;
  switch (type) {
    case ElementType::kBytes: return "bytes";
    case ElementType::kFloat32: return "f32";
    case ElementType::kFloat64: return "f64";
    case ElementType::kInt32: return "i32";
    case ElementType::kUint32: return "u32";
    case ElementType::kJson: return "json";
  }
  return "?";
}

const fapcast::cli::Registration voice_build_command{"voice build", [](CLI::App& app) {
  struct Args {
    std::string corpus;
    std::string output;
    std::string pca = "exact";
    std::uint64_t seed = 1;
    int em_iterations = 300;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = fapcast::cli::command_group(app, "voice", kVoiceGroupHelp)
                  ->add_subcommand("build",
                                   "Build a voice from a corpus directory (manifest.json, or markers *.c3d, *.trc or "
                                   "*.csv, each with a *.TextGrid or *.lab of the same stem): prototypes, RBF retargeting onto the ICT face, PCA, phone graph");
  cmd->add_option("CORPUS", args->corpus, "Corpus directory")->required();
  cmd->add_option("-o,--output", args->output, "Voice file to write (.fapv)")->required();
  cmd->add_option("--pca", args->pca, "PCA route: exact (the RBF map's affine image) or em (EM-PCA, minutes)")
      ->check(CLI::IsMember({"exact", "em"}))
      ->capture_default_str();
  cmd->add_option("--em-iterations", args->em_iterations, "EM-PCA: at most this many passes after the mean pass")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of EM-PCA's start (recorded in the provenance)")->capture_default_str();
  cmd->add_flag("-q,--quiet", args->quiet, "No progress on standard error");
  cmd->callback([args] {
    fapcast::cli::check_output_writable(args->output);
    fapcast::VoiceBuildOptions options;
    options.pca = args->pca == "em" ? fapcast::PcaRoute::em : fapcast::PcaRoute::exact;
    options.seed = args->seed;
    options.em_max_iterations = args->em_iterations;
    options.build_time_utc = fapcast::cli::voice_build_time_utc();
    options.tool_version = FAPCAST_VERSION;
    options.progress = [&](std::string_view stage, std::size_t done, std::size_t total) {
      if (args->quiet || (stage == "read" && done % 25 != 0 && done != total)) return;
      std::cerr << "\rvoice build: " << stage << " " << done << " / " << total << "        " << std::flush;
    };
    const auto voice = fapcast::build_voice(args->corpus, options);
    if (!args->quiet) std::cerr << "\n";
    fapcast::write_file_atomically(args->output, voice.bytes);
    const auto& s = voice.summary;
    std::cout << "voice " << args->output << ": " << s.frames << " frames, " << s.utterances << " utterances, "
              << s.states << " phone states, " << s.prototypes << " prototypes (target rank " << s.target_rank
              << "), r^2 " << s.r_squared_m2 << " m^2, lambda " << s.lambda << (s.lambda_at_range_edge ? " (range edge)" : "")
              << ", " << pca_route_name(options.pca) << " PCA explains " << std::setprecision(6)
              << 100 * s.explained_fraction << " %";
    std::cout << ", " << s.pattern_filled_gaps << " long marker gaps pattern-filled";
    if (s.lip_contact)
      std::cout << ", lip contact at " << 1000 * s.source_contact_m << " mm (source) / " << 1000 * s.target_contact_m
                << " mm (target), " << s.lip_contact_frames << " frames closed further";
    if (options.pca == fapcast::PcaRoute::em)
      std::cout << " after " << s.pca_iterations << " EM passes" << (s.pca_converged ? "" : " (not converged)");
    std::cout << ", " << voice.bytes.size() << " bytes; read " << s.seconds_read
              << " s, fit " << s.seconds_fit << " s, pca " << s.seconds_pca << " s, total " << s.seconds_total << " s\n";
  });
}};

const fapcast::cli::Registration voice_info_command{"voice info", [](CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto* cmd = fapcast::cli::command_group(app, "voice", kVoiceGroupHelp)
                  ->add_subcommand("info", "Print a voice's provenance and the size of each section");
  cmd->add_option("VOICE", *path, "Voice file (.fapv)")->required();
  cmd->callback([path] {
    const auto voice = fapcast::Voice::open(*path);
    const auto& p = voice.provenance();
    std::cout << "voice:        " << *path << "\n"
              << "corpus:       " << p.corpus << "\n"
              << "target face:  " << p.target_face << "\n"
              << "seed:         " << p.seed << "\n"
              << "synthetic:    " << (p.synthetic ? "yes" : "no") << "\n";
    if (p.synthetic) std::cout << "label:        " << fapcast::kSyntheticLabel << "\n";
    std::cout << "built:        " << p.build_time_utc << " by fapcast " << p.tool_version << "\n";
    for (const auto& [name, value] : p.parameters) std::cout << "  " << std::left << std::setw(24) << name << value << "\n";
    for (const auto& [name, text] : p.notes) std::cout << "  " << std::left << std::setw(24) << name << text << "\n";
    std::cout << "k " << voice.component_count() << ", D " << voice.dimension() << ", frames "
              << voice.frame_coefficients().rows() << ", phone states " << voice.graph().size() << ", utterances "
              << voice.utterance_frames().size() << ", feature points " << voice.feature_points().size()
              << ", RBF centres " << voice.retarget_map().centre_count() << "\n";
    if (const auto& contact = voice.retargeting().contact())
      std::cout << "lip contact:  source " << 1000 * contact->source_contact_m << " mm, target "
                << 1000 * contact->target_contact_m << " mm, reach " << 1000 * contact->reach_m
                << " mm (spec/voice.md, \"Lip contact\")\n";
    else
      std::cout << "lip contact:  none (the retargeting is the map alone)\n";
    std::cout << "sections (" << voice.file().sections().size() << ", " << voice.file().file_size() << " bytes):\n";
    for (const auto& s : voice.file().sections())
      std::cout << "  " << s.id.str() << "  " << std::left << std::setw(20) << fapcast::section_name(s.id)
                << std::setw(6) << element_type_name(s.type) << std::right << std::setw(8) << s.rows << " x "
                << std::left << std::setw(8) << s.cols << std::right << std::setw(12) << s.size << " bytes\n";
  });
}};

}  // namespace

namespace {

const fapcast::cli::Registration voice_default_command{"voice default", [](CLI::App& app) {
  auto quiet = std::make_shared<bool>(false);
  auto* cmd = fapcast::cli::command_group(app, "voice", kVoiceGroupHelp)
                  ->add_subcommand("default",
                                   "Build the default voice (SYNTHETIC reference corpus, seed 1) into the cache "
                                   "unless it is there, and print its path");
  cmd->add_flag("-q,--quiet", *quiet, "No progress on standard error");
  cmd->callback([quiet] { std::cout << fapcast::cli::ensure_default_voice(*quiet).string() << "\n"; });
}};

}  // namespace

namespace {

const fapcast::cli::Registration voice_adapt_command{"voice adapt", [](CLI::App& app) {
  struct Args {
    std::string voice, generic, specific, output, unit = "cm";
  };
  auto args = std::make_shared<Args>();
  auto* cmd = fapcast::cli::command_group(app, "voice", kVoiceGroupHelp)
                  ->add_subcommand("adapt",
                                   "Adapt a voice to a specific face of its face's topology without "
                                   "re-recording: per-vertex affine maps carry the PCA mean and components, the "
                                   "RBF map and the neutral feature points (spec/adaptation.md)");
  cmd->add_option("VOICE", args->voice, "Voice file (.fapv)")->required();
  cmd->add_option("GENERIC", args->generic, "The voice's own neutral face (.obj), e.g. the ICT generic mesh")
      ->required();
  cmd->add_option("SPECIFIC", args->specific, "The specific neutral face (.obj), same topology")->required();
  cmd->add_option("--obj-unit", args->unit, "Length unit of both OBJ files")
      ->check(CLI::IsMember({"cm", "m", "mm"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", args->output, "The adapted voice (.fapv, written atomically)")->required();
  cmd->callback([args] {
    fapcast::cli::check_output_writable(args->output);
    const float metres = args->unit == "cm" ? 0.01f : args->unit == "mm" ? 0.001f : 1.0f;
    const auto generic = fapcast::read_obj_mesh(args->generic);
    const auto specific = fapcast::read_obj_mesh(args->specific);
    fapcast::require_same_topology(generic, args->generic, specific, args->specific);
    const auto voice = fapcast::Voice::open(args->voice);
    fapcast::AdaptedVoice out;
    try {
      out = fapcast::adapt_voice(voice, metres * generic.vertices, metres * specific.vertices, generic.faces,
                                           std::filesystem::path(args->specific).filename().string());
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(args->generic + ": " + e.what());
    }
    fapcast::write_file_atomically(args->output, out.bytes);
    const auto& s = out.summary;
    std::cout << "voice " << args->output << ": " << voice.component_count() << " components adapted over "
              << s.vertices << " vertices, " << s.triangles << " triangles (" << s.degenerate_triangles
              << " degenerate, " << s.global_map_vertices << " vertices on the global map); feature points moved by "
              << "up to " << s.max_feature_point_offset_m * 1000.0 << " mm; " << out.bytes.size() << " bytes\n";
  });
}};

}  // namespace
