#pragma once
// How well the recogniser (recognise/) times real recordings against their reference labels:
// with the transcript, the share of reference phone boundaries within 10/20/25/50 ms
// (boundary_agreement.hpp); without it, the share of 10 ms frames whose phone falls in the
// reference phone's search viseme class. Per data set, over the vendored references listed by
// reference_recordings (spec/recognise.md, "Accuracy").
#include <span>
#include <string>
#include <vector>

#include "fapcast/core/sample_rate.hpp"
#include "fapcast/eval/boundary_agreement.hpp"
#include "fapcast/phonetics/timed_phone.hpp"

#include <nlohmann/json.hpp>

namespace fapcast {

// The `frame_s` frames over the reference's extent (centres at its start + (k + 0.5) frame_s) and
// how many of them have a hypothesis phone of the reference phone's search viseme class
// (silence is its own class).
struct FrameAgreement {
  std::size_t frames = 0;
  std::size_t in_class = 0;
  double share() const { return frames ? static_cast<double>(in_class) / static_cast<double>(frames) : 0; }
};

FrameAgreement viseme_frame_agreement(std::span<const TimedPhone> reference, std::span<const TimedPhone> hypothesis,
                              SampleRate sample_rate, double frame_s = 0.010);

// One vendored recording with reference phone labels and its transcript.
struct ReferenceRecording {
  std::string set;         // "EMU ae", "MOCHA-TIMIT" ...
  std::string name;        // "msajc003"
  std::string wav;         // paths
  std::string labels;      // read by read_alignment_file (the format found by its rules)
  std::string transcript;  // a UTF-8 text file
  bool machine = false;    // the labels come from another aligner, not a person
};

// The references under `data_dir` (the repository's tests/data), hand-labelled: EMU ae msajc x 7,
// MOCHA-TIMIT fsew0_001, Praat's examples (praatIO's mary, Parselmouth's north wind; praatIO's bobby has a label no
// phone set reads, "PT");
// machine-labelled, reported apart: CMU ARCTIC slt a0009 (HTS forced alignment) and MFA's
// michael (Montreal Forced Aligner).
std::vector<ReferenceRecording> reference_recordings(const std::string& data_dir);

struct AlignmentScore {
  std::string set;
  std::size_t recordings = 0;
  double seconds = 0;              // of speech
  BoundaryAgreement boundaries;    // with the transcript: every reference boundary (counts summed)
  FrameAgreement frames;           // without it: the recognition's frames (summed)
};

// Aligns (with the transcript) and recognises (without) every recording, and scores both against
// its labels; one score per set in the order of `recordings`, then "all hand-labelled" when two
// sets or more are, every recording read in the accent `language` (AlignerSettings::language:
// an espeak-ng language, empty for the US dictionary only). Throws InputError for unreadable
// files; a recording the aligner refuses is an error.
std::vector<AlignmentScore> evaluate_alignment(std::span<const ReferenceRecording> recordings,
                                               const std::string& language = {});

// The scores as a text table (one row per set: recordings, seconds, boundaries and their share
// within 10/20/25/50 ms, frames and their share in class), headed by `command` (what reproduces it).
std::string format_alignment_table(std::span<const AlignmentScore> scores, const std::string& command);
// The same as JSON: {"command", "sets": [{"set", "recordings", "seconds", "boundaries",
// "within_ms": {"10", "20", "25", "50"}, "frames", "frames_in_class", "frame_share"}]}; shares 0..1.
nlohmann::json alignment_json(std::span<const AlignmentScore> scores, const std::string& command);

}  // namespace fapcast
