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
  int source_channels = 1;             // channels of the file read (> 1: downmixed to this one)
};

// Most channels read_wav downmixes (a WAV may declare up to 65535).
inline constexpr int kMaxWavChannels = 64;

// Writes 16-bit PCM mono WAV atomically (a temporary file in the same directory, renamed over
// `path`). Throws std::runtime_error naming the file and libsndfile's reason.
void write_wav(const std::filesystem::path& path, const MonoAudio& audio);

// Reads a WAV (any PCM/float encoding libsndfile reads, converted to int16). Two or more
// channels (at most kMaxWavChannels) are downmixed to their mean, rounded to the nearest
// integer (halves away from zero); source_channels says how many there were. Refuses more than
// `max_samples` samples (frames; counted while reading, the header is not trusted).
// Throws std::runtime_error naming the file.
MonoAudio read_wav(const std::filesystem::path& path, std::int64_t max_samples = 1ll << 31);

}  // namespace fapcast
