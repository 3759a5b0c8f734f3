// libFuzzer: any bytes as a sound file through both WAV readers, read_wav (libsndfile, with the
// RIFF data-chunk length check) and read_mono_wav. Either InputError, or audio whose samples are
// whole instants of at least one channel at a positive rate, read alike by both when mono.
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fuzz/support/scratch_file.hpp"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const auto path = fuzz::scratch_file("in.wav", {reinterpret_cast<const char*>(data), size});
  constexpr std::int64_t kLimit = 1 << 20;  // instants: keeps one run's memory small
  Audio audio;
  try {
    audio = read_wav(path, kLimit);
  } catch (const InputError&) {
    return 0;
  }
  if (audio.channels < 1 || audio.sample_rate.hz < 1 || audio.instants() > kLimit ||
      audio.samples.size() % static_cast<std::size_t>(audio.channels) != 0)
    std::abort();
  try {
    const Audio mono = read_mono_wav(path, kLimit);
    if (audio.channels != 1 || mono.samples != audio.samples) std::abort();
  } catch (const InputError& e) {
    if (audio.channels == 1 || e.rule() != "wav-mono") std::abort();
  }
  return 0;
}
