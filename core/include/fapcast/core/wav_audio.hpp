#pragma once
// Reading the audio a FAP track is timed against, with libsndfile: WAV and every other format it
// supports, any sample rate and channel count, delivered as interleaved 16-bit samples.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace fapcast {

struct WavAudio {
  std::int64_t sample_rate = 0;        // sampling instants per second (>= 1)
  int channels = 0;                    // >= 1
  std::vector<std::int16_t> samples;   // interleaved: instant i, channel c at i * channels + c

  // Sampling instants ("frames" in libsndfile's words).
  std::int64_t instants() const {
    return channels > 0 ? static_cast<std::int64_t>(samples.size()) / channels : 0;
  }
};

// Longest audio read_multichannel_wav accepts by default: four hours.
inline constexpr std::int64_t kDefaultMaxWavSeconds = 4 * 3600;

// Reads a whole sound file. Throws std::runtime_error naming the file and the reason (cannot
// open, not a sound file libsndfile knows, no channels, longer than `max_seconds`). Reads in
// chunks and never allocates from the header's claimed length.
WavAudio read_multichannel_wav(const std::filesystem::path& path,
                  std::int64_t max_seconds = kDefaultMaxWavSeconds);

}  // namespace fapcast
