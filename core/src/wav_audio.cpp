#include "fapcast/core/wav_audio.hpp"

#include <sndfile.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace fapcast {
namespace {
struct SndfileCloser {
  void operator()(SNDFILE* f) const { sf_close(f); }
};
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error(path.string() + ": " + what);
}
}  // namespace

WavAudio read_multichannel_wav(const std::filesystem::path& path, std::int64_t max_seconds) {
  SF_INFO info{};
  std::unique_ptr<SNDFILE, SndfileCloser> file(sf_open(path.c_str(), SFM_READ, &info));
  if (!file) fail(path, std::string("wav-open: cannot read as audio: ") + sf_strerror(nullptr));
  if (info.channels < 1 || info.channels > 1024) fail(path, "wav-channels: unsupported channel count");
  if (info.samplerate < 1) fail(path, "wav-rate: sample rate must be positive");
  WavAudio audio;
  audio.sample_rate = info.samplerate;
  audio.channels = info.channels;
  const std::int64_t max_instants = max_seconds * info.samplerate;
  constexpr sf_count_t kChunkInstants = 4096;
  std::vector<std::int16_t> chunk(static_cast<std::size_t>(kChunkInstants) * info.channels);
  for (;;) {
    const sf_count_t got = sf_readf_short(file.get(), chunk.data(), kChunkInstants);
    if (got <= 0) break;
    if (audio.instants() + got > max_instants)
      fail(path, "wav-too-long: longer than " + std::to_string(max_seconds) + " s");
    audio.samples.insert(audio.samples.end(), chunk.begin(),
                         chunk.begin() + static_cast<std::ptrdiff_t>(got * info.channels));
  }
  if (sf_error(file.get()) != SF_ERR_NO_ERROR)
    fail(path, std::string("wav-read: ") + sf_strerror(file.get()));
  return audio;
}

}  // namespace fapcast
