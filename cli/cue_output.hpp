#pragma once
// `say|animate --cues-out FILE [--cues-format tsv|xml|json] [--extended-shapes GHX]`: the phones
// as 2D mouth cues in Rhubarb Lip Sync's result formats (spec/mouth-cues.md), for the tools and
// integrations written for Rhubarb.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include <CLI/CLI.hpp>

#include "fapcast/core/sample_rate.hpp"
#include "fapcast/cues/rhubarb_format.hpp"
#include "fapcast/phonetics/timed_phone.hpp"

namespace fapcast::cli {

struct CueArgs {
  std::string output;                  // --cues-out FILE
  std::string format_name;             // --cues-format (default: the output's extension)
  std::string extended = "GHX";        // --extended-shapes, Rhubarb's --extendedShapes
  std::string sound_file;              // the recording the metadata names (set by the command)
  std::optional<RhubarbFormat> format; // resolved before the run (check_cue_args)
};

void add_cue_options(CLI::App& command, CueArgs& args);

// Checks the options before any work and resolves the format (UsageError).
void check_cue_args(const std::string& command, CueArgs& args);

// Writes the cues of `phones` (on a recording of `audio_samples` at `rate`) atomically to
// args.output; returns a summary for the command's line ("; 42 mouth cues in OUT.tsv").
std::string write_cue_output(const CueArgs& args, std::span<const TimedPhone> phones, SampleRate rate,
                             std::int64_t audio_samples);

}  // namespace fapcast::cli
