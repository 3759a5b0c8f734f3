#pragma once
// The clock of a WAV timeline: sampling instants per second. Every track of an utterance (phones,
// voice frames, FAP frames, RTP timestamps) is timed in samples of its audio's rate.
#include <cstdint>
#include <ostream>

namespace fapcast {

struct SampleRate {
  std::int64_t hz = 0;  // >= 1 when valid, e.g. 22050 for espeak-ng, 48000 for RTP's default clock
  constexpr bool valid() const { return hz >= 1; }
  friend constexpr bool operator==(SampleRate, SampleRate) = default;
};

inline std::ostream& operator<<(std::ostream& out, SampleRate rate) { return out << rate.hz << " Hz"; }

}  // namespace fapcast
