#pragma once
// The command shape shared by `say` and `animate`: one sub-command with the synthesis options
// (output, voice, rate, search parameters, expression), and the common run: timed phones in, an
// animation file out.
#include "animation.hpp"
#include "cue_output.hpp"
#include "rig_output.hpp"

#include "fapcast/synthesis/speech_expression.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast::cli {

struct SynthesisArgs {
  std::string voice;  // empty: the default voice
  std::string output;  // empty only with cues.output: the cues alone
  int fps = 25;
  bool fps_given = false;
  SynthesisOptions options;  // the library's defaults unless an option says otherwise
  bool viseme = false;
  bool quiet = false;
  std::string obj_frames;  // .glb only: also every frame as OBJ here (debugging)
  std::string player;      // .fap only: --player xface|greta|vreng
  std::string expression_text;                     // as given: "joy:40[,surprise:20]"
  std::optional<ExpressionBlend> expression;  // parsed before `run` is called
  RigArgs rig;                     // --rig, --avatar, --vmc (spec/rigs.md)
  CueArgs cues;                    // --cues-out, --cues-format, --extended-shapes (spec/mouth-cues.md)
  std::vector<TimedWord> words;  // the words spoken and their spans (say), for the TalkingHead JSON
  double piece_seconds = 30.0;  // say: a FAP track is made in pieces of this much speech (0: at once)
};

// The options that shape the synthesis, shared by `say`, `animate` and `eval synth`: --beta,
// --max-active, --duration-weight, --boundary-joins, bound to `options`, whose current values
// (the library's defaults) are the defaults --help shows.
void add_synthesis_options(CLI::App& cmd, SynthesisOptions& options);

// The synthesis options in which `options` differs from the library's defaults, as the
// command-line text that asks for them (" --beta 0 --max-active 0"), for reports.
std::string synthesis_options_text(const SynthesisOptions& options);

// Adds the sub-command `name` to `app` with -o, --voice, --fps, the synthesis options, --viseme,
// --expression, --obj-frames-out, -q; the caller adds its own inputs to the returned command. On a parse it checks
// the output's extension and the options that do not apply to it (UsageError, before any work),
// parses the expression into args.expression, then calls `run`.
CLI::App* add_synthesis_command(CLI::App& app, const std::string& name, const std::string& description,
                                SynthesisArgs& args, std::function<void()> run);

// The voice args.voice names (the default voice when empty), checked against this build's phone
// set (check_voice_phone_set), and the name it goes by in messages.
Voice open_synthesis_voice(const SynthesisArgs& args);
std::string synthesis_voice_name(const SynthesisArgs& args);

// The FAP track's options the arguments ask for: --fps, --viseme, --expression (FAP 2), `name`.
AnimationOptions animation_options(const SynthesisArgs& args, std::string name);

// What `say` and `animate` report when a track is written.
struct SynthesisReport {
  std::size_t frames = 0;
  int fps = 0;
  double audio_seconds = 0.0;
  std::size_t phones = 0;
  std::size_t units = 0;
  std::size_t pieces = 1;  // > 1: the track was made in pieces cut in pauses
  double synthesis_ms = 0.0;
  std::size_t substituted = 0;  // phones that borrowed a nearby viseme class
  std::size_t dropped = 0;      // phones shorter than a frame
};

// The one-line summary: "OUT: F frames at R fps (S s), P phones in U units[ (N pieces cut in
// pauses)], synthesised in T ms[, expression E]", then `outputs` (the rig's and the cues' parts),
// then the substituted and dropped phones when there are any. No line end.
std::string synthesis_summary(const SynthesisArgs& args, const SynthesisReport& report, std::string_view outputs);

// Writes the mouth cues of `phones` when asked (args.cues), then synthesises them (at
// `sample_rate`, audio of `audio_samples`) on the voice and writes args.output (FAPs, or a .glb of
// the PCA frames) unless only cues were asked for; prints a one-line summary. `source` names the
// phones in errors.
void synthesize_to_file(const SynthesisArgs& args, std::span<const TimedPhone> phones,
                        SampleRate sample_rate, std::int64_t audio_samples,
                        const std::string& source, const std::string& name);

}  // namespace fapcast::cli
