// `say` on a page of text against espeak-ng alone on the same page, in the same run: what the
// front-end (phone events, mapping, closure search) and the animation (synthesize: grid, unit
// search, concatenation, tongue) cost on top of the TTS. The animation runs on a graph of the
// paper corpus's size with SYNTHETIC class shapes (tests/support/synthetic_voice_graph.hpp), a
// stand-in for a voice's search data. BM_SayVsEspeak times both in each iteration on the
// thread's CPU clock (espeak-ng runs synchronously in it; robust on a shared machine) and reports
// their ratio (say_over_espeak_cpu); counters audio_s_per_s are seconds of speech per wall second.
#include <benchmark/benchmark.h>
#include <espeak-ng/speak_lib.h>

#include <time.h>

#include <string>
#include <vector>

#include "fapcast/frontend/text_frontend.hpp"
#include "fapcast/synthesis/synthesis.hpp"
#include "support/synthetic_voice_graph.hpp"

namespace {
using namespace fapcast;

// About a page (3,000 bytes, 520 words, 3 minutes at espeak-ng's 175 wpm).
const std::string kPage =
    "Most people who need lip sync have a recording, not a phone alignment. Game dialogue, an "
    "audiobook, a teacher explaining a lesson, a voice on a live microphone: each comes as sound, "
    "sometimes with a script beside it. The method this program follows builds a face from motion "
    "capture. An actor reads a script chosen to cover the phones of the language in many contexts, "
    "while cameras follow markers on the lips, the jaw and the cheeks. Every recording is cut into "
    "phones, and every phone keeps the short stretch of motion that went with it. To speak a new "
    "sentence, the program first turns the text into phones and their timing. Then it searches "
    "the recordings for the sequence of stretches that matches those phones best, preferring long "
    "runs that were recorded together, because a run that was spoken in one breath already "
    "carries the right coarticulation. Where two stretches meet, their motion is warped in time "
    "and blended, so that the lips do not jump. The result is a track of facial animation "
    "parameters, frame by frame, in step with the audio. "
    "How well does it work? The paper behind it compared the synthesised motion with motion that "
    "was captured but held out of the corpus, and with the motion of a simpler method that picks "
    "one stretch per phone. Listeners watched both and were asked which looked more natural. The "
    "longer units won, most clearly on fast speech, where a single phone hardly has time to reach "
    "its target before the next one begins. Measures on the markers told the same story: the "
    "error of the lip opening fell, and the timing of closures for the sounds p, b and m moved "
    "closer to the truth. "
    "There are limits. A corpus covers one speaker, one language and one speaking style; a voice "
    "that was recorded calm will not shout convincingly. The tongue is hardly visible and is "
    "estimated rather than captured. Emotion changes the whole face, not only the mouth, so it is "
    "added as a separate layer on top of the speech. And the text front-end decides a great deal: "
    "if it puts a pause in the wrong place, or reads a number the wrong way, the face will follow "
    "it faithfully. That is why the phones come from a real speech synthesiser, whose timing is "
    "the timing of the sound that will be played. "
    "Would you like to try it? Write a sentence, choose a voice, and ask for a track at "
    "twenty-five frames per second. Play the sound and the track together in a viewer, and watch "
    "the lips close for every b, round for every w, and open wide for the vowel in father. Then "
    "try a long paragraph, a question, a list of numbers, and a sentence in another language.";

constexpr double kRateHz = 22050.0;

const test::SyntheticVoiceGraph& voice() {
  static const test::SyntheticVoiceGraph v = test::synthetic_voice_graph(1400, 30, 5, 17, 42, 0.1f);
  return v;
}

std::vector<short>* g_audio = nullptr;
int copy_audio_only(short* wav, int n, espeak_EVENT*) {
  if (wav != nullptr && n > 0) g_audio->insert(g_audio->end(), wav, wav + n);
  return 0;
}

// espeak_Synth of the page with a callback that keeps the audio and ignores every event.
std::size_t espeak_bare(std::vector<short>& audio) {
  audio.clear();
  g_audio = &audio;
  espeak_SetSynthCallback(copy_audio_only);
  espeak_Synth(kPage.c_str(), kPage.size() + 1, 0, POS_CHARACTER, 0, espeakCHARS_UTF8, nullptr, nullptr);
  espeak_Synchronize();
  return audio.size();
}

// What `say` does up to the PCA frames: the front-end, then the animation.
std::size_t say_page() {
  const Speech speech = speak(kPage);
  const auto track = synthesize(*voice().graph, voice().frames, speech.phones, speech.audio.sample_rate, 0, {});
  benchmark::DoNotOptimize(track.pca_frames.data());
  return speech.audio.samples.size();
}

void audio_rate(benchmark::State& state, std::size_t samples) {
  state.counters["audio_s_per_s"] = benchmark::Counter(static_cast<double>(samples) / kRateHz, benchmark::Counter::kIsRate);
}

void BM_EspeakBare(benchmark::State& state) {
  speak("");  // initialises espeak-ng (en-us, synchronous) once
  std::vector<short> audio;
  std::size_t samples = 0;
  for (auto _ : state) samples += espeak_bare(audio);
  audio_rate(state, samples);
}
BENCHMARK(BM_EspeakBare)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_FrontEnd(benchmark::State& state) {
  std::size_t samples = 0;
  for (auto _ : state) {
    const Speech speech = speak(kPage);
    samples += speech.audio.samples.size();
    benchmark::DoNotOptimize(speech.phones.data());
  }
  audio_rate(state, samples);
}
BENCHMARK(BM_FrontEnd)->Unit(benchmark::kMillisecond)->UseRealTime();

// The animation alone, from the page's phones.
void BM_Animation(benchmark::State& state) {
  const Speech speech = speak(kPage);
  (void)voice();
  for (auto _ : state) {
    const auto track = synthesize(*voice().graph, voice().frames, speech.phones, speech.audio.sample_rate, 0, {});
    benchmark::DoNotOptimize(track.pca_frames.data());
  }
  audio_rate(state, speech.audio.samples.size() * static_cast<std::size_t>(state.iterations()));
}
BENCHMARK(BM_Animation)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SayVsEspeak(benchmark::State& state) {
  speak("");
  (void)voice();
  std::vector<short> audio;
  double espeak_s = 0.0, say_s = 0.0;
  std::size_t samples = 0;
  const auto cpu_s = [] {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
  for (auto _ : state) {
    const double t0 = cpu_s();
    espeak_bare(audio);
    const double t1 = cpu_s();
    samples += say_page();
    const double t2 = cpu_s();
    espeak_s += t1 - t0;
    say_s += t2 - t1;
  }
  state.counters["say_over_espeak_cpu"] = say_s / espeak_s;
  state.counters["say_audio_s_per_cpu_s"] = static_cast<double>(samples) / kRateHz / say_s;
}
BENCHMARK(BM_SayVsEspeak)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same page in another language (IPA events mapped through features): what IPA mode costs.
void BM_FrontEndGerman(benchmark::State& state) {
  SpeakOptions de;
  de.language = "de";
  std::size_t samples = 0;
  for (auto _ : state) {
    const Speech speech = speak(kPage, de);
    samples += speech.audio.samples.size();
    benchmark::DoNotOptimize(speech.phones.data());
  }
  audio_rate(state, samples);
}
BENCHMARK(BM_FrontEndGerman)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
