#pragma once
// Builds phone timelines for the talker tests: phones with durations in milliseconds, at 22050 Hz.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "fapcast/talker/coarticulation.hpp"

namespace fapcast::test {

inline constexpr std::int32_t kRate = 22050;

// Consecutive phones, each (symbol, duration_ms), starting at sample 0.
inline PhoneTimeline timeline(const std::vector<std::pair<std::string, int>>& phones) {
  PhoneTimeline t{SampleRate{kRate}, {}};
  std::int64_t at = 0;
  for (const auto& [phone, ms] : phones) {
    const std::int64_t end = at + std::int64_t{ms} * kRate / 1000;
    t.phones.push_back({parse_arpabet(phone, "test timeline").phone, at, end});
    at = end;
  }
  return t;
}

// Centre of phone i in seconds.
inline double centre_s(const PhoneTimeline& t, std::size_t i) {
  return 0.5 * static_cast<double>(t.phones[i].start_sample + t.phones[i].end_sample) / static_cast<double>(t.sample_rate.hz);
}

// The random seed for randomised tests: $FAPCAST_SEED, default 20061.
inline std::uint64_t test_seed() {
  const char* s = std::getenv("FAPCAST_SEED");
  return s != nullptr ? std::strtoull(s, nullptr, 10) : 20061u;
}

}  // namespace fapcast::test
