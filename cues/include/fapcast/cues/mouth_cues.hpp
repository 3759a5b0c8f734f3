#pragma once
// Mouth cues from timed phones: which of the nine mouth shapes to show from when to when, by the
// rules of spec/mouth-cues.md (each phone's allowed shapes, anticipation of vowels, pauses,
// in-betweens). Cues are timed in centiseconds, Rhubarb Lip Sync's resolution.
#include <chrono>
#include <cstdint>
#include <span>
#include <vector>

#include "fapcast/core/sample_rate.hpp"
#include "fapcast/cues/mouth_shape.hpp"
#include "fapcast/phonetics/timed_phone.hpp"

namespace fapcast {

using Centiseconds = std::chrono::duration<std::int64_t, std::centi>;

struct MouthCue {
  MouthShape shape;
  Centiseconds start;
  Centiseconds end;  // the next cue's start; the last cue's is the recording's length
  friend bool operator==(const MouthCue&, const MouthCue&) = default;
};

struct MouthCueOptions {
  MouthShapeSet drawn = MouthShapeSet::all();  // the shapes the character has (drawn_shapes())
};

// The sample `sample` at `rate` truncated to centiseconds (Rhubarb truncates times and lengths).
Centiseconds truncated_centiseconds(std::int64_t sample, SampleRate rate);

// The cues of `phones` (in time order, not overlapping, on the timeline of a recording of
// `audio_samples` samples at `rate`): contiguous from 0 to truncated_centiseconds(audio_samples),
// no cue empty, no two neighbours alike, every shape in options.drawn. Time the phones leave
// uncovered, and SIL, is a pause. Throws std::invalid_argument when the phones are out of order or
// overlap (a caller's bug: alignments are checked when read).
std::vector<MouthCue> mouth_cues(std::span<const TimedPhone> phones, SampleRate rate, std::int64_t audio_samples,
                                 const MouthCueOptions& options = {});

}  // namespace fapcast
