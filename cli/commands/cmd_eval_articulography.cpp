// `fapcast eval articulography EMA SPEECH.wav [ALIGNMENT] [--transcript FILE | --text TEXT] [--lang L] [--voice V]
// [--by-phone] [--json-out FILE] [--svg-out FILE]`: animates a recording as `animate` does (from its phone
// alignment, or from the phones fapcast finds in it) and compares the face with the talker's real
// articulography (spec/articulography.md, "Evaluation against articulography"). With both an
// ALIGNMENT and a transcript it animates both ways and says how much fapcast's own alignment
// changes the scores. Argument parsing only.
#include "command.hpp"
#include "default_voice.hpp"
#include "output_check.hpp"
#include "recorded_speech.hpp"
#include "speech_transcript.hpp"
#include "synthesis_cli.hpp"
#include "fapcast/utterance/voice_face.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/corpus/ema.hpp"
#include "fapcast/eval/articulography_evaluation.hpp"
#include "fapcast/eval/svg_plot.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace {
using namespace fapcast;

std::string shell_word(const std::string& s) {
  return s.find_first_of(" \t\"'") == std::string::npos ? s : "\"" + s + "\"";
}

const cli::Registration eval_articulography_command{"eval articulography", [](CLI::App& app) {
  struct Args {
    std::string ema;
    std::string wav;
    std::string align;
    cli::AlignmentArgs alignment;
    cli::TranscriptArgs transcript;
    std::string voice;
    SynthesisOptions options;
    double tilt_deg = 0;
    bool talker = false;
    bool by_phone = false;
    std::string json;
    std::string svg;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = cli::command_group(app, "eval", cli::kEvalGroupHelp)
                  ->add_subcommand("articulography",
                                   "Animate a recording and compare the face's lips, jaw and tongue tip with the "
                                   "talker's real articulography (MOCHA-TIMIT EMA): range ratio, r, best lag");
  cmd->add_option("EMA", args->ema, "The talker's articulography: MOCHA-TIMIT EMA (EST Track ASCII or binary, or bare rows)")
      ->required();
  cmd->add_option("SPEECH", args->wav, "The recording the EMA was taken with (WAV): the timeline")->required();
  cmd->add_option("ALIGNMENT", args->align,
                  "Its phone alignment (any format `animate` reads; MOCHA's .lab labels read as the mocha set); or "
                  "none: the phones are found with --transcript or --text, else by recognising the speech");
  cli::add_transcript_options(*cmd, args->transcript);
  cli::add_alignment_options(*cmd, args->alignment);
  cmd->add_option("--voice", args->voice, "Voice file (default: the reference voice, built on first use)");
  cli::add_synthesis_options(*cmd, args->options);
  cmd->add_option("--tilt", args->tilt_deg,
                  "Degrees added to the registration's head-pitch rotation (+ turns the coils' up towards forward): "
                  "how much the scores depend on it")
      ->check(CLI::Range(-45.0, 45.0))
      ->capture_default_str();
  cmd->add_flag("--talker", args->talker,
                "Also animate each alignment with the SYNTHETIC reference talker's own articulation (the tracks the "
                "default voice is recorded from, on the generic ICT face, no voice): whether an error comes from the "
                "talker's tables or from the voice");
  cmd->add_flag("--by-phone", args->by_phone,
                "Also print, per animation, each phone's share of 1 - r (lips, jaw, protrusion): where the "
                "correlation is lost");
  cmd->add_option("--json-out", args->json, "Write the results as JSON to this file (atomically)");
  cmd->add_option("--svg-out", args->svg, "Write the curves, real and synthesised, as an SVG plot to this file (atomically)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress on standard error");
  cmd->callback([args] {
    if (args->transcript.file_given() && args->transcript.text_given())
      throw cli::UsageError("eval articulography: give what the speech says with --transcript FILE or --text TEXT, not both");
    if (args->align.empty() && (!args->alignment.tier.empty() || !args->alignment.phone_set.empty()))
      throw cli::UsageError("eval articulography: --tier and --phone-set read an ALIGNMENT file");
    if (!args->align.empty() && !args->transcript.given() && !args->transcript.lang.empty())
      throw cli::UsageError("eval articulography: --lang is the accent of the own alignment: give --transcript or --text too");
    cli::check_output_writable(args->json);  // before the voice is read and the speech animated
    cli::check_output_writable(args->svg);
    const MarkerFrames<Millimetres> ema = read_ema(read_file(args->ema), args->ema);
    std::string command = "fapcast eval articulography " + shell_word(args->ema) + " " + shell_word(args->wav);
    if (!args->align.empty()) command += " " + shell_word(args->align);
    if (args->transcript.file_given()) command += " --transcript " + shell_word(args->transcript.file);
    if (args->transcript.text_given()) command += " --text " + shell_word(args->transcript.text);
    if (!args->transcript.lang.empty()) command += " --lang " + shell_word(args->transcript.lang);
    if (!args->voice.empty()) command += " --voice " + shell_word(args->voice);
    command += cli::synthesis_options_text(args->options);
    if (args->talker) command += " --talker";
    if (args->by_phone) command += " --by-phone";
    ArticulographySettings settings;
    settings.extra_rotation_rad = args->tilt_deg * std::numbers::pi / 180;
    if (args->tilt_deg != 0) {
      std::ostringstream tilt;
      tilt << " --tilt " << args->tilt_deg;
      command += tilt.str();
    }

    // The phones first (the reference alignment's, then fapcast's own), checked against the EMA
    // before the voice is opened.
    struct Animation {
      std::string name;
      std::string source;
      cli::RecordedPhones speech;
    };
    std::vector<Animation> animations;
    if (!args->align.empty())
      animations.push_back({"reference alignment", args->align,
                            cli::phones_from_alignment(args->wav, args->align, args->alignment, "eval articulography",
                                                       args->quiet)});
    if (args->align.empty() || args->transcript.given())
      animations.push_back({std::string(args->transcript.given() ? "own alignment (forced, transcript" : "own alignment (recognised") +
                                ", accent " + (args->transcript.lang.empty() ? "US dictionary" : args->transcript.lang) + ")",
                            args->wav, cli::phones_from_recording(args->wav, args->transcript, args->quiet)});
    for (const Animation& a : animations)
      check_articulography_inputs(ema, args->ema, a.speech.phones, a.speech.sample_rate, a.source);

    const Voice voice = cli::open_voice_or_default(args->voice, args->quiet);
    const std::string voice_name = args->voice.empty() ? std::string("the default voice") : args->voice;
    check_voice_phone_set(voice, voice_name);
    std::vector<ArticulographyEvaluation> evaluations;
    std::vector<std::string> names;
    for (const Animation& a : animations) {
      evaluations.push_back(evaluate_articulography(ema, args->ema, voice, a.speech.phones, a.speech.sample_rate,
                                                    a.speech.samples, args->options, a.source, settings));
      names.push_back(a.name);
    }
    // After the voice's animations, so that the first two stay the reference and own alignment's.
    const std::size_t voice_evaluations = evaluations.size();
    if (args->talker) {
      for (const Animation& a : animations) {
        evaluations.push_back(evaluate_talker_articulography(ema, args->ema, voice, a.speech.phones,
                                                             a.speech.sample_rate, a.speech.samples, args->options,
                                                             a.source, settings));
        names.push_back("reference talker (SYNTHETIC), " + a.name);
      }
    }

    std::cout << "# " << command << "\n";
    std::cout << "Real articulography " << args->ema << " against the face animated on " << voice_name
              << " (ICT face points 8.1, 8.2, 2.1, incisor tips; the parametric tongue's tip)\n\n";
    nlohmann::json json;
    json["command"] = command;
    json["ema"] = args->ema;
    json["speech"] = args->wav;
    json["voice"] = voice_name;
    for (std::size_t i = 0; i < evaluations.size(); ++i) {
      const bool talker = i >= voice_evaluations;
      std::cout << articulography_table(evaluations[i], talker ? "## the " + names[i] + ", no voice"
                                                               : "## animated from the " + names[i])
                << "\n";
      if (args->by_phone)
        std::cout << articulography_loss_table(evaluations[i], "where r is lost, phone by phone (1 - r = the sum of "
                                                               "the rows; each row sums (z ours - z real)^2 / 2n):")
                  << "\n";
      nlohmann::json one = articulography_json(evaluations[i]);
      one["phones_from"] = names[i];
      one["animated_by"] = i >= voice_evaluations ? "reference talker (SYNTHETIC)" : "voice";
      json["animations"].push_back(std::move(one));
    }
    if (voice_evaluations == 2) {
      std::cout << "## own alignment against the reference alignment\n"
                << alignment_effect_table(evaluations[0], evaluations[1]) << "\n";
    }
    if (!args->json.empty()) write_file_atomically(args->json, json.dump(2) + "\n");
    if (!args->svg.empty()) {
      const std::string title = std::filesystem::path(args->ema).filename().string() +
                                ": real articulography against the face on " + voice_name;
      write_file_atomically(args->svg, svg_line_plot(articulography_plot(evaluations, names, title)));
    }
  });
}};

}  // namespace
