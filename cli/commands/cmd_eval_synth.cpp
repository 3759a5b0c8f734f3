// `fapcast eval synth`: the held-out evaluation of synthesis (spec/evaluation.md): SYNTHETIC
// sentences recorded by the voice's reference actor, synthesised from their own phone timing by
// the variable-length search and two baselines, scored on the target face.
#include "command.hpp"
#include "default_voice.hpp"
#include "synthesis_cli.hpp"
#include "fapcast/eval/svg_plot.hpp"
#include "fapcast/eval/synthesis_report.hpp"

#include "fapcast/face/face_model.hpp"
#include "fapcast/eval/held_out_sentences.hpp"
#include "fapcast/eval/synthesis_evaluation.hpp"
#include "fapcast/synthesis/synthesis.hpp"
#include "fapcast/voice/voice.hpp"
#include "fapcast/core/file_io.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace {
using namespace fapcast;

// The method under test: synthesize() - the Viterbi search over the voice's phone graph and
// concatenate_units - from the utterance's own timed phones, as `fapcast say` runs it.
NamedSystem variable_length_system(const Voice& voice, SynthesisOptions options) {
  return {"variable-length", [&voice, options, guide = jaw_guide_for(voice, options)](const HeldOutUtterance& u) {
            const auto track = synthesize(voice.graph(), voice.frame_coefficients(), u.speech.phones,
                                                 u.speech.audio.sample_rate,
                                                 static_cast<std::int64_t>(u.speech.audio.samples.size()), options, u.id,
                                                 guide ? &*guide : nullptr);
            return SystemOutput{track.pca_frames, track.search.units.size()};
          }};
}

const cli::Registration eval_synth_command{"eval synth", [](CLI::App& app) {
  struct Args {
    std::string voice;
    std::size_t count = kHeldOutSentences.size();
    std::uint64_t seed = 2;
    std::string plots;
    std::string json;
    SynthesisOptions options;  // the library's defaults: what `say` ships
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = cli::command_group(app, "eval", cli::kEvalGroupHelp)
                  ->add_subcommand("synth",
                                   "Held-out SYNTHETIC sentences recorded by the voice's reference actor, "
                                   "synthesised from their own timing by the variable-length search, diviseme "
                                   "concatenation and dominance interpolation; lip and feature-point errors");
  cmd->add_option("VOICE", args->voice, "Voice file (.fapv); default: the cached default voice, built on first use");
  cmd->add_option("--count", args->count, "Held-out sentences to record and synthesise")
      ->check(CLI::Range(std::size_t{1}, kHeldOutSentences.size()))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the held-out takes' variation (the voice's corpus uses its own)")
      ->capture_default_str();
  cli::add_synthesis_options(*cmd, args->options);
  cmd->add_option("--plots-out", args->plots, "Write one SVG of lip curves per sentence into this folder (created)");
  cmd->add_option("--json-out", args->json, "Write the results as JSON to this file (atomically)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress on standard error");
  cmd->callback([args] {
    namespace fs = std::filesystem;
    const fs::path voice_path = args->voice.empty() ? cli::ensure_default_voice(args->quiet) : fs::path(args->voice);
    const auto voice = Voice::open(voice_path);
    const FaceModel actor = held_out_actor(voice);
    if (!args->quiet) std::cerr << "recording " << args->count << " held-out sentences (seed " << args->seed << ")\n";
    const auto held = record_held_out(actor, args->seed, args->count);
    const SynthesisOptions& options = args->options;
    const std::vector<NamedSystem> systems{
        variable_length_system(voice, options),
        diviseme_system(voice.graph(), voice.frame_coefficients()),
        diviseme_system(voice.graph(), voice.frame_coefficients(), {}, DivisemeChoiceRule::kFirst),
        dominance_system(voice.graph(), voice.frame_coefficients())};
    const auto report = evaluate_synthesis(evaluation_face(voice), systems, held);

    std::ostringstream command;
    command << "fapcast eval synth" << (args->voice.empty() ? "" : " " + args->voice) << " --count " << args->count
            << " --seed " << args->seed << cli::synthesis_options_text(options);
    const fapcast::EvaluationContext context{voice_path.string(), args->seed, command.str()};
    std::cout << fapcast::format_evaluation_table(report, context);
    if (!args->json.empty())
      write_file_atomically(args->json, fapcast::evaluation_json(report, context).dump(2) + "\n");
    if (!args->plots.empty()) {
      fs::create_directories(args->plots);
      for (std::size_t u = 0; u < report.utterances.size(); ++u)
        write_file_atomically(fs::path(args->plots) / (report.utterances[u].id + ".svg"),
                                         fapcast::svg_line_plot(fapcast::lip_curve_plot(report, u)));
    }
  });
}};

}  // namespace
