#pragma once
// Mono 16-bit PCM audio and its WAV file form (libsndfile). Time is in samples at
// sample_rate_hz, the timeline every other track of an utterance refers to.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace fapcast {

struct MonoAudio {
  int sample_rate_hz = 0;              // e.g. 22050 for espeak-ng
  std::vector<std::int16_t> samples;   // one channel, linear PCM
};

// Writes 16-bit PCM mono WAV atomically (a temporary file in the same directory, renamed over
// `path`). Throws std::runtime_error naming the file and libsndfile's reason.
void write_wav(const std::filesystem::path& path, const MonoAudio& audio);

// Reads a mono WAV (any PCM/float encoding libsndfile reads, converted to int16). Refuses files
// with more than one channel or more than `max_samples` samples (checked before reading).
// Throws std::runtime_error naming the file.
MonoAudio read_wav(const std::filesystem::path& path, std::int64_t max_samples = 1ll << 31);

}  // namespace fapcast
