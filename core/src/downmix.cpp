#include "fapcast/core/downmix.hpp"

#include <cstddef>
#include <cstdint>
#include <stdexcept>

namespace fapcast {

Audio downmix_to_mono(const Audio& audio) {
  if (audio.channels < 1) throw std::invalid_argument("downmix: channel count must be positive");
  if (audio.channels == 1) return audio;
  Audio mono;
  mono.sample_rate = audio.sample_rate;
  mono.channels = 1;
  const auto channels = static_cast<std::size_t>(audio.channels);
  const auto instants = static_cast<std::size_t>(audio.instants());
  mono.samples.reserve(instants);
  const auto n = static_cast<std::int64_t>(channels);
  for (std::size_t i = 0; i < instants; ++i) {
    std::int64_t sum = 0;
    for (std::size_t c = 0; c < channels; ++c) sum += audio.samples[i * channels + c];
    mono.samples.push_back(static_cast<std::int16_t>((sum >= 0 ? sum + n / 2 : sum - n / 2) / n));
  }
  return mono;
}

}  // namespace fapcast
