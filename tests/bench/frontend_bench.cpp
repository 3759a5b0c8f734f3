// The text front-end against bare espeak-ng synthesis of the same text: what phone events,
// mapping and closure search cost on top of synthesis. Counters: phones per second and seconds
// of audio per second (the inverse real-time factor); compare BM_FrontEnd with BM_EspeakBare.
#include <benchmark/benchmark.h>
#include <espeak-ng/speak_lib.h>

#include <cstring>
#include <string>
#include <vector>

#include "fapcast/frontend/text_frontend.hpp"

namespace {

const std::string kText =
    "The method starts from a motion capture corpus of about fourteen hundred utterances. "
    "Peter picked a peck of pickled peppers, and Bob bought a big blue boat. "
    "Would you like a cup of coffee before we begin the recording session this morning?";

void BM_FrontEnd(benchmark::State& state) {
  std::size_t phones = 0, samples = 0;
  for (auto _ : state) {
    const auto speech = fapcast::speak(kText);
    phones += speech.phones.size();
    samples += speech.audio.samples.size();
    benchmark::DoNotOptimize(speech.phones.data());
  }
  state.counters["phones_per_s"] = benchmark::Counter(static_cast<double>(phones), benchmark::Counter::kIsRate);
  state.counters["audio_s_per_s"] = benchmark::Counter(static_cast<double>(samples) / 22050.0, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FrontEnd)->Unit(benchmark::kMillisecond)->UseRealTime();

std::vector<short>* g_audio = nullptr;
int copy_audio_only(short* wav, int n, espeak_EVENT*) {
  if (wav != nullptr && n > 0) g_audio->insert(g_audio->end(), wav, wav + n);
  return 0;
}

// espeak_Synth with a callback that keeps the audio and ignores every event.
void BM_EspeakBare(benchmark::State& state) {
  fapcast::speak("");  // initialises espeak-ng (en-us, synchronous) once
  std::vector<short> audio;
  g_audio = &audio;
  std::size_t samples = 0;
  for (auto _ : state) {
    audio.clear();
    espeak_SetSynthCallback(copy_audio_only);
    espeak_Synth(kText.c_str(), kText.size() + 1, 0, POS_CHARACTER, 0, espeakCHARS_UTF8, nullptr, nullptr);
    espeak_Synchronize();
    samples += audio.size();
    benchmark::DoNotOptimize(audio.data());
  }
  state.counters["audio_s_per_s"] = benchmark::Counter(static_cast<double>(samples) / 22050.0, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EspeakBare)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
