#pragma once
// What `animate` and `eval articulography` share for a recording: its timed phones, read from a
// phone alignment (--tier, --phone-set) on the WAV's timeline, or found in the WAV by the forced
// aligner with its transcript, or by recognition without one (spec/recognise.md).
#include "speech_transcript.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "fapcast/core/sample_rate.hpp"
#include "fapcast/phonetics/timed_phone.hpp"

namespace fapcast::cli {

// The ALIGNMENT file's options.
struct AlignmentArgs {
  std::string tier;       // --tier
  std::string phone_set;  // --phone-set
};

void add_alignment_options(CLI::App& command, AlignmentArgs& args);

// Timed phones on a WAV's timeline.
struct RecordedPhones {
  std::vector<TimedPhone> phones;
  SampleRate sample_rate{16000};
  std::int64_t samples = 0;  // the audio's length
};

// The phones of the alignment file `alignment` on the timeline of the WAV `wav` (two or more
// channels downmixed): read by read_alignment_file with `args` (UsageError for an unknown
// --phone-set, naming `command`), cut to the audio with a 20 ms tolerance; notes and a warning
// for an alignment that ends early on standard error unless `quiet`.
RecordedPhones phones_from_alignment(const std::string& wav, const std::string& alignment, const AlignmentArgs& args,
                                     const std::string& command, bool quiet);

// The phones found in the WAV by align_recording (its transcript, or recognition).
RecordedPhones phones_from_recording(const std::string& wav, const TranscriptArgs& transcript, bool quiet);

}  // namespace fapcast::cli
