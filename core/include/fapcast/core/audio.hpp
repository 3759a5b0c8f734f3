#pragma once
// Linear 16-bit PCM audio: the timeline every other track of an utterance refers to (time in
// samples at sample_rate). Speech is mono; a sound file read for streaming may have more
// channels, interleaved.
#include "fapcast/core/sample_rate.hpp"

#include <cstdint>
#include <vector>

namespace fapcast {

struct Audio {
  SampleRate sample_rate;              // e.g. 22050 Hz for espeak-ng
  int channels = 1;                    // >= 1
  std::vector<std::int16_t> samples;   // interleaved: instant i, channel c at i * channels + c

  // Sampling instants ("frames" in libsndfile's words): samples.size() / channels.
  std::int64_t instants() const {
    return channels > 0 ? static_cast<std::int64_t>(samples.size()) / channels : 0;
  }
};

}  // namespace fapcast
