#pragma once
// What an aligner or recogniser found in a recording: contiguous segments (phones, silences,
// noises and stretches that match no transcript word) and the words, on the recording's own
// WAV timeline (samples at its rate). spec/recognise.md, "Output".
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fapcast/core/sample_rate.hpp"
#include "fapcast/corpus/alignment.hpp"
#include "fapcast/phonetics/timed_phone.hpp"

namespace fapcast {

enum class SpeechSegmentKind : std::uint8_t {
  phone,      // a speech sound of the phone set
  silence,    // a pause (lips at rest)
  noise,      // breath, lip smack, cough, background noise: not speech, not a phone
  unmatched,  // speech the transcript does not account for (only in a mismatch's diagnosis)
};

struct SpeechSegment {
  SpeechSegmentKind kind = SpeechSegmentKind::silence;
  Phone phone = Phone::SIL;    // SIL for every kind but phone
  std::int64_t start_sample = 0;
  std::int64_t end_sample = 0;  // = the next segment's start
  int word = -1;                // index into SpeechAlignment::words, -1 outside words
  double score_per_frame = 0;   // the recogniser's acoustic score (decoder.hpp), nats per frame
  friend bool operator==(const SpeechSegment&, const SpeechSegment&) = default;
};

struct SpeechWord {
  std::string text;             // as written in the transcript (recognised: the dictionary word)
  std::size_t byte_offset = 0;  // in the transcript (recognised: 0)
  std::int64_t start_sample = 0;
  std::int64_t end_sample = 0;
  double score_per_frame = 0;   // frame-weighted mean of its phones' scores
  bool low_confidence = false;  // score below kLowConfidenceScore
  friend bool operator==(const SpeechWord&, const SpeechWord&) = default;
};

// Words scoring below this (nats per frame) are marked low_confidence: on the real recordings
// of spec/recognise.md it flags 2 of 118 correct words and 47 of 62 words swapped for another.
inline constexpr double kLowConfidenceScore = -3.6;

struct SpeechAlignment {
  SampleRate sample_rate;
  std::int64_t samples = 0;  // the recording's length; the last segment ends here
  std::vector<SpeechSegment> segments;
  std::vector<SpeechWord> words;
};

// The segments as phones for synthesis: silence, noise and unmatched speech become SIL.
std::vector<TimedPhone> timed_phones(const SpeechAlignment& alignment);

// A TextGrid's tiers: "phones" (ARPAbet; silence is the empty label, noise "spn", unmatched
// speech "unk") and "words" (the words as written; gaps empty).
Alignment to_alignment(const SpeechAlignment& alignment);

}  // namespace fapcast
