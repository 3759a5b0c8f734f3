#include "fapcast/recognise/resample.hpp"

#include <samplerate.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fapcast/core/downmix.hpp"

namespace fapcast {

namespace {

bool in_range(SampleRate r) { return r.hz >= kMinSpeechRate.hz && r.hz <= kMaxSpeechRate.hz; }

std::int16_t to_pcm(float v) {
  return static_cast<std::int16_t>(std::clamp<long>(std::lround(static_cast<double>(v) * 32768.0), -32768L, 32767L));
}

}  // namespace

Audio resample_mono(const Audio& audio, SampleRate rate) {
  if (!in_range(rate) || !in_range(audio.sample_rate))
    throw std::invalid_argument("resample_mono: rates must be 8000..192000 Hz (from " +
                                std::to_string(audio.sample_rate.hz) + " to " + std::to_string(rate.hz) + ")");
  Audio mono = downmix_to_mono(audio);
  if (rate == mono.sample_rate) return mono;
  std::vector<float> in(mono.samples.size());
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = static_cast<float>(mono.samples[i]) / 32768.0f;
  const double ratio = static_cast<double>(rate.hz) / static_cast<double>(mono.sample_rate.hz);
  std::vector<float> out(static_cast<std::size_t>(std::ceil(static_cast<double>(in.size()) * ratio)) + 16);
  SRC_DATA data{};
  data.data_in = in.data();
  data.input_frames = static_cast<long>(in.size());
  data.data_out = out.data();
  data.output_frames = static_cast<long>(out.size());
  data.src_ratio = ratio;
  if (const int err = src_simple(&data, SRC_SINC_MEDIUM_QUALITY, 1); err != 0)
    throw std::logic_error(std::string("libsamplerate: ") + src_strerror(err));
  Audio result;
  result.sample_rate = rate;
  result.channels = 1;
  result.samples.resize(static_cast<std::size_t>(data.output_frames_gen));
  for (std::size_t i = 0; i < result.samples.size(); ++i) result.samples[i] = to_pcm(out[i]);
  return result;
}

}  // namespace fapcast
