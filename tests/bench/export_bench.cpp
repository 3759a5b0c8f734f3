// BVH and JSON export speed in frames per second on a ten-minute synthetic track (SYNTHETIC:
// patterned values, the mask Xface writes), each beside a printf baseline that writes the same
// numbers with no structure, so the ratio shows what the formats cost.
//   build/dev/tests/export_bench --benchmark_counters_tabular=true
#include "fapcast/codec/bvh_export.hpp"
#include "fapcast/codec/bvh_text.hpp"
#include "fapcast/codec/json_export.hpp"
#include "support/fap_sequences.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

namespace {
using namespace fapcast;

constexpr std::size_t kFrames = 25 * 600;  // ten minutes at 25 fps

const FapSequence& track() {
  static const FapSequence seq = test::realistic_fap_sequence(kFrames);
  return seq;
}
const FaceGeometry& face() {
  static const FaceGeometry f = generic_adult_face();
  return f;
}

void per_frame(benchmark::State& state, std::size_t bytes) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kFrames));
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(state.iterations() * kFrames), benchmark::Counter::kIsRate);
  state.counters["bytes/frame"] = static_cast<double>(bytes) / kFrames;
}

// FAP track -> rig -> BVH text: the whole export.
void BM_BvhExport(benchmark::State& state) {
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string text = write_bvh(fap_to_bvh(track(), face()));
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  per_frame(state, bytes);
}

// Only the text writing (shortest round-trip numbers via std::to_chars).
void BM_BvhWriteOnly(benchmark::State& state) {
  const BvhDocument doc = fap_to_bvh(track(), face());
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string text = write_bvh(doc);
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  per_frame(state, bytes);
}

// Baseline: the same motion numbers with snprintf("%.6f"), no hierarchy, no checks.
void BM_BvhPrintfBaseline(benchmark::State& state) {
  const BvhDocument doc = fap_to_bvh(track(), face());
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::string text;
    char buf[64];
    const std::size_t width = doc.channel_count();
    for (std::size_t i = 0; i < doc.motion.size(); ++i) {
      const int n = std::snprintf(buf, sizeof buf, (i + 1) % width ? "%.6f " : "%.6f\n", doc.motion[i]);
      text.append(buf, static_cast<std::size_t>(n));
    }
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  per_frame(state, bytes);
}

void BM_BvhRead(benchmark::State& state) {
  const std::string text = write_bvh(fap_to_bvh(track(), face()));
  for (auto _ : state) benchmark::DoNotOptimize(read_bvh(text, "bench.bvh").motion.data());
  per_frame(state, text.size());
}

void BM_JsonExport(benchmark::State& state) {
  const FapJsonOptions options{SampleRate{16000}, std::nullopt, "bench"};
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string text = write_fap_json(track(), options);
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  per_frame(state, bytes);
}

// Baseline: the same named values with snprintf, one flat line per frame, no JSON library.
void BM_JsonPrintfBaseline(benchmark::State& state) {
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::string text;
    char buf[96];
    std::int64_t k = 0;
    for (const FapFrame& f : track().frames) {
      int n = std::snprintf(buf, sizeof buf, "%lld %.17g %lld", static_cast<long long>(k),
                            static_cast<double>(k) / 25.0,
                            static_cast<long long>(frame_to_sample(k, {25, 1}, SampleRate{16000})));
      text.append(buf, static_cast<std::size_t>(n));
      for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap) {
        if (!f.mask.test(fap)) continue;
        const std::string_view name = fap_info(fap).name;
        n = std::snprintf(buf, sizeof buf, " %.*s=%d", static_cast<int>(name.size()), name.data(),
                          f.value(fap));
        text.append(buf, static_cast<std::size_t>(n));
      }
      text += '\n';
      ++k;
    }
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  per_frame(state, bytes);
}

void BM_JsonRead(benchmark::State& state) {
  const std::string text = write_fap_json(track(), {SampleRate{16000}, std::nullopt, "bench"});
  for (auto _ : state)
    benchmark::DoNotOptimize(read_fap_json(text, "bench.json").sequence.frames.data());
  per_frame(state, text.size());
}

BENCHMARK(BM_BvhExport)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BvhWriteOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BvhPrintfBaseline)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BvhRead)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JsonExport)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JsonPrintfBaseline)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JsonRead)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
