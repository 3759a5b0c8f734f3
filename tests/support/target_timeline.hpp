#pragma once
// Target phones on the voice's 60 fps grid for the synthesis tests: each phone held a number of
// frames, from frame 0, as place_on_voice_grid lays them.
#include <cstdint>
#include <initializer_list>
#include <utility>

#include "fapcast/voice/voice_frame_grid.hpp"

namespace fapcast::test {

inline TargetTimeline target_timeline(std::initializer_list<std::pair<Phone, std::int64_t>> phones) {
  TargetTimeline t;
  t.sample_rate = SampleRate{16000};
  std::int64_t at = 0;
  for (const auto& [phone, frames] : phones) {
    t.phones.push_back({search_viseme(phone), at, at + frames, false});
    t.phone_of.push_back(phone);
    at += frames;
  }
  return t;
}

}  // namespace fapcast::test
