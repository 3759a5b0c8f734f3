#pragma once
// A frame rate as an exact rational (25/1, 30000/1001), and the frame <-> sample arithmetic
// that keeps animation frames on the WAV timeline without drift.
#include "fapcast/core/sample_rate.hpp"

#include <compare>
#include <cstdint>
#include <ostream>

namespace fapcast {

struct FrameRate {
  std::uint32_t numerator = 25;   // frames ...
  std::uint32_t denominator = 1;  // ... per this many seconds; both >= 1

  double fps() const { return static_cast<double>(numerator) / denominator; }
  bool valid() const { return numerator >= 1 && denominator >= 1; }
  // Compares the rates, not the spelling: 50/2 == 25/1.
  bool operator==(const FrameRate& o) const {
    return std::uint64_t{numerator} * o.denominator == std::uint64_t{o.numerator} * denominator;
  }
};

std::ostream& operator<<(std::ostream& out, FrameRate rate);

// The sample at which frame k starts on a timeline of `sample_rate`:
// round(k * sample_rate * denominator / numerator), exact integer arithmetic (half rounds up).
// Preconditions: rate.valid(), k >= 0, sample_rate.valid().
std::int64_t frame_to_sample(std::int64_t k, FrameRate rate, SampleRate sample_rate);

// The frame shown at `sample`: the last frame k with frame_to_sample(k) <= sample.
std::int64_t sample_to_frame(std::int64_t sample, FrameRate rate, SampleRate sample_rate);

// The first frame shown at or after `sample` (>= 0): the smallest k with
// frame_to_sample(k) >= sample, in closed form (the frame a phone starting at `sample` owns).
std::int64_t first_frame_at(std::int64_t sample, FrameRate rate, SampleRate sample_rate);

}  // namespace fapcast
