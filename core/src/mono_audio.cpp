#include "fapcast/core/mono_audio.hpp"

#include <sndfile.h>

#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>

namespace fapcast {

namespace {

struct SndfileCloser {
  void operator()(SNDFILE* f) const { sf_close(f); }
};
using SndfilePtr = std::unique_ptr<SNDFILE, SndfileCloser>;

std::runtime_error wav_error(const std::filesystem::path& path, const std::string& what) {
  return std::runtime_error(path.string() + ": " + what);
}

}  // namespace

void write_wav(const std::filesystem::path& path, const MonoAudio& audio) {
  if (audio.sample_rate_hz <= 0) throw wav_error(path, "sample rate must be positive");
  // Unique temporary name in the target directory, so the rename is atomic on one file system.
  std::random_device rd;
  std::filesystem::path tmp = path;
  tmp += ".tmp" + std::to_string(rd());
  SF_INFO info{};
  info.samplerate = audio.sample_rate_hz;
  info.channels = 1;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  {
    SndfilePtr file(sf_open(tmp.c_str(), SFM_WRITE, &info));
    if (!file) throw wav_error(path, std::string("cannot create: ") + sf_strerror(nullptr));
    const auto n = static_cast<sf_count_t>(audio.samples.size());
    if (sf_write_short(file.get(), audio.samples.data(), n) != n) {
      const std::string reason = sf_strerror(file.get());
      file.reset();
      std::filesystem::remove(tmp);
      throw wav_error(path, "write failed: " + reason);
    }
    sf_write_sync(file.get());
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp);
    throw wav_error(path, "rename failed: " + ec.message());
  }
}

MonoAudio read_wav(const std::filesystem::path& path, std::int64_t max_samples) {
  SF_INFO info{};
  SndfilePtr file(sf_open(path.c_str(), SFM_READ, &info));
  if (!file) throw wav_error(path, std::string("cannot read audio: ") + sf_strerror(nullptr));
  if (info.channels < 1 || info.channels > kMaxWavChannels) {
    throw wav_error(path, "cannot downmix " + std::to_string(info.channels) + " channels (at most " +
                              std::to_string(kMaxWavChannels) + ")");
  }
  // Read in blocks: the header's frame count is not trusted for an allocation.
  MonoAudio audio;
  audio.sample_rate_hz = info.samplerate;
  audio.source_channels = info.channels;
  const auto channels = static_cast<std::size_t>(info.channels);
  const std::size_t frames_per_block = (std::size_t{1} << 16) / channels;
  std::vector<std::int16_t> block(frames_per_block * channels);
  for (;;) {
    const sf_count_t got = sf_readf_short(file.get(), block.data(), static_cast<sf_count_t>(frames_per_block));
    if (got <= 0) break;
    if (static_cast<std::int64_t>(audio.samples.size()) + got > max_samples) {
      throw wav_error(path, "too many samples (limit " + std::to_string(max_samples) + ")");
    }
    if (channels == 1) {
      audio.samples.insert(audio.samples.end(), block.begin(), block.begin() + got);
      continue;
    }
    for (sf_count_t f = 0; f < got; ++f) {
      std::int32_t sum = 0;
      for (std::size_t c = 0; c < channels; ++c) sum += block[static_cast<std::size_t>(f) * channels + c];
      const auto n = static_cast<std::int32_t>(channels);
      audio.samples.push_back(static_cast<std::int16_t>((sum >= 0 ? sum + n / 2 : sum - n / 2) / n));
    }
  }
  return audio;
}

}  // namespace fapcast
