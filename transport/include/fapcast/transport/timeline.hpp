#pragma once
// The WAV timeline: every animation frame carries the sample at which it starts, so animation
// and sound share one clock (the audio sample rate) and never drift apart.
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/codec/fap_frame.hpp"

#include <chrono>
#include <cstdint>
#include <vector>

namespace fapcast {

// Default timeline clock when there is no WAV: 48 kHz, a common audio rate that every common
// frame rate (24, 25, 30, 50, 60 and the 1001-rates up to rounding) divides well.
inline constexpr SampleRate kDefaultSampleRate{48'000};

struct TimedFrame {
  std::int64_t sample = 0;  // first sample of the WAV timeline at which the frame is shown
  FapFrame frame;
  bool operator==(const TimedFrame&) const = default;
};

// The time of `sample` on a clock of `sample_rate`, truncated to whole nanoseconds, and the
// number of whole samples in a duration; exact integer arithmetic (no drift at any length).
std::chrono::nanoseconds samples_to_duration(std::int64_t sample, SampleRate sample_rate);
std::int64_t duration_to_samples(std::chrono::nanoseconds t, SampleRate sample_rate);

// Places frame k of `seq` at frame_to_sample(k, seq.rate, sample_rate).
// Preconditions: seq.rate.valid(), sample_rate.valid().
std::vector<TimedFrame> place_on_timeline(const FapSequence& seq, SampleRate sample_rate);

}  // namespace fapcast
