#pragma once
// The command shape shared by `say` and `animate`: one sub-command with the synthesis options
// (output, voice, rate, search parameters, expression), and the common run: timed phones in, an
// animation file out.
#include "animation.hpp"
#include "rig_output.hpp"

#include "fapcast/synthesis/speech_expression.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fapcast::cli {

struct SynthesisArgs {
  std::string voice;  // empty: the default voice
  std::string output;
  int fps = 25;
  bool fps_given = false;
  double beta = 0.1;
  std::size_t max_active = 64;  // 0 = no cap
  double duration_weight = 0.0;
  bool boundary_joins = false;  // units take over at phone boundaries, not mid-phone
  bool viseme = false;
  bool quiet = false;
  std::string obj_frames;  // .glb only: also every frame as OBJ here (debugging)
  std::string expression_text;                     // as given: "joy:40[,surprise:20]"
  std::optional<ExpressionBlend> expression;  // parsed before `run` is called
  RigArgs rig;                     // --rig, --avatar, --vmc (spec/rigs.md)
  std::vector<std::string> words;  // the words spoken (say), for the TalkingHead JSON
};

// Adds the sub-command `name` to `app` with -o, --voice, --fps, --beta, --max-active, --viseme,
// --expression, --obj-frames, -q; the caller adds its own inputs to the returned command. On a parse it checks
// the output's extension and the options that do not apply to it (UsageError, before any work),
// parses the expression into args.expression, then calls `run`.
CLI::App* add_synthesis_command(CLI::App& app, const std::string& name, const std::string& description,
                                SynthesisArgs& args, std::function<void()> run);

// Synthesises `phones` (at `sample_rate_hz`, audio of `audio_samples`) on the voice and writes
// args.output (FAPs, or a .glb of the PCA frames); prints a one-line summary. `source` names the
// phones in errors.
void synthesize_to_file(const SynthesisArgs& args, std::span<const TimedPhone> phones,
                        std::int64_t sample_rate_hz, std::int64_t audio_samples,
                        const std::string& source, const std::string& name);

}  // namespace fapcast::cli
