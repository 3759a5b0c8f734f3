#pragma once
// Options and the common run of `say` and `animate`: voice, rate, search parameters; timed
// phones in, an animation file out.
#include "animation.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <span>
#include <string>

namespace fapcast::tools {

struct SynthesisArgs {
  std::string voice;  // empty: the default voice
  std::string output;
  int fps = 25;
  double beta = 0.1;
  std::size_t max_active = 64;  // 0 = no cap
  bool viseme = false;
  bool quiet = false;
};

// Adds -o, --voice, --fps, --beta, --max-active, --viseme, -q to `cmd`.
void add_synthesis_options(CLI::App* cmd, SynthesisArgs& args);

// Refuses (UsageError) an output whose extension no writer handles, before any work is done.
void check_animation_output(const std::string& command, const SynthesisArgs& args);

// Synthesises `phones` (at `sample_rate_hz`, audio of `audio_samples`) on the voice and writes
// args.output; prints a one-line summary. `source` names the phones in errors.
void synthesize_to_file(const SynthesisArgs& args, std::span<const synth::TimedPhone> phones,
                        std::int64_t sample_rate_hz, std::int64_t audio_samples,
                        const std::string& source, const std::string& name);

}  // namespace fapcast::tools
