#pragma once
// Builds phone timelines for the talker tests: phones with durations in milliseconds, at 22050 Hz.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "fapcast/talker/coarticulation.hpp"
#include "support/test_seed.hpp"

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

// The default seed of the randomised talker and preprocessing tests (support/test_seed.hpp).
inline constexpr std::uint64_t kTimelineSeed = 20061;

}  // namespace fapcast::test
