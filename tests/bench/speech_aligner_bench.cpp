// Forced alignment's speed in audio seconds per CPU second (counter x_real_time), on the 7 EMU ae
// recordings with their transcripts (21.6 s of speech), beside the obvious alternatives in the
// same run: the model's own 100 frames per second (every frame scored) against the default 200
// with scores every second frame, and the default with the word-edge pass (spec/recognise.md).
// Recognition without the transcript (the word 3-gram, then the alignment of the words heard) on
// the same recordings, beside the alignment with it. A long recording (the 7 joined end to end,
// 3 times over: 64 s) aligned piece by piece, cut at its pauses, beside the same in one piece.
#include "fapcast/core/file_io.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/recognise/resample.hpp"
#include "fapcast/recognise/speech_aligner.hpp"

#include <benchmark/benchmark.h>

#include <string>
#include <utility>
#include <vector>

namespace {

using namespace fapcast;

struct Take {
  Audio audio;
  Transcript transcript;
};

const std::vector<Take>& takes() {
  static const std::vector<Take> all = [] {
    std::vector<Take> out;
    const std::string emu = std::string(FAPCAST_TEST_DATA) + "/speech/emu-ae/";
    for (const char* u : {"msajc003", "msajc010", "msajc012", "msajc015", "msajc022", "msajc023", "msajc057"})
      out.push_back({read_wav(emu + u + ".wav"), parse_transcript(read_file(emu + u + ".txt"), u)});
    return out;
  }();
  return all;
}

double total_seconds() {
  double seconds = 0;
  for (const Take& t : takes())
    seconds += static_cast<double>(t.audio.instants()) / static_cast<double>(t.audio.sample_rate.hz);
  return seconds;
}

void align_all(benchmark::State& state, AlignerSettings settings) {
  SpeechAligner aligner(settings);
  const double seconds = total_seconds();
  (void)aligner.align(takes().front().audio, takes().front().transcript, "warm-up");  // the model loads once
  for (auto _ : state)
    for (const Take& t : takes()) benchmark::DoNotOptimize(aligner.align(t.audio, t.transcript, "bench"));
  state.counters["x_real_time"] =
      benchmark::Counter(seconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_Align200FpsOnePass(benchmark::State& state) { align_all(state, {}); }
// The default without the weak forms of function words (spec/recognise.md, "Weak forms"): what they cost.
void BM_Align200FpsNoWeakForms(benchmark::State& state) { align_all(state, {.weak_forms = false}); }
void BM_Align100FpsOnePass(benchmark::State& state) { align_all(state, {.frames_per_second = 100}); }
void BM_Align200FpsWordEdges(benchmark::State& state) { align_all(state, {.word_edges = true}); }

void BM_RecogniseThenAlign(benchmark::State& state) {
  SpeechAligner aligner;
  const double seconds = total_seconds();
  (void)aligner.recognise(takes().front().audio, "warm-up");  // the model and the 3-gram load once
  for (auto _ : state)
    for (const Take& t : takes()) benchmark::DoNotOptimize(aligner.recognise(t.audio, "bench"));
  state.counters["x_real_time"] =
      benchmark::Counter(seconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The 7 takes joined end to end `times` times over, with their transcripts one after the other.
Take joined(int times) {
  Take out;
  std::string text;
  for (int k = 0; k < times; ++k)
    for (const Take& t : takes()) {
      out.audio.sample_rate = t.audio.sample_rate;
      out.audio.samples.insert(out.audio.samples.end(), t.audio.samples.begin(), t.audio.samples.end());
      text += t.transcript.text + "\n";
    }
  out.transcript = parse_transcript(text, "joined");
  return out;
}

void align_long(benchmark::State& state, AlignerSettings settings) {
  SpeechAligner aligner(settings);
  const Take take = joined(3);
  const double seconds = static_cast<double>(take.audio.instants()) / static_cast<double>(take.audio.sample_rate.hz);
  (void)aligner.align(takes().front().audio, takes().front().transcript, "warm-up");
  for (auto _ : state) benchmark::DoNotOptimize(aligner.align(take.audio, take.transcript, "bench"));
  state.counters["x_real_time"] =
      benchmark::Counter(seconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_AlignLong64sInPieces(benchmark::State& state) { align_long(state, {}); }
void BM_AlignLong64sOnePiece(benchmark::State& state) { align_long(state, {.in_pieces = false}); }

// What share of the alignment's time is the resampling to 16 kHz (libsamplerate's medium sinc),
// on the same recordings.
void BM_ResampleTo16k(benchmark::State& state) {
  const double seconds = total_seconds();
  for (auto _ : state)
    for (const Take& t : takes()) benchmark::DoNotOptimize(resample_mono(t.audio, SampleRate{16000}));
  state.counters["x_real_time"] =
      benchmark::Counter(seconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_ResampleTo16k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Align200FpsOnePass)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Align200FpsNoWeakForms)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RecogniseThenAlign)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Align100FpsOnePass)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Align200FpsWordEdges)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AlignLong64sInPieces)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AlignLong64sOnePiece)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
