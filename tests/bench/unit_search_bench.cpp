// Unit search speed on a graph the size of the paper's corpus (1,400 recordings x 30 phones,
// 21 viseme classes, k = 17 PCA coefficients at 60 fps), built from random visemes and random
// PCA frames: a stand-in for a voice with the same shape, not a voice. A 10-second target of
// 120 phones is searched with beta = 0 (units only), beta > 0 (smoothness) and with a cap on the
// active states; counters report seconds of animation per CPU second and active states.
#include "fapcast/synthesis/unit_concatenation.hpp"
#include "fapcast/select/unit_search.hpp"
#include "fapcast/core/eigen_types.hpp"

#include <benchmark/benchmark.h>
#include <malloc.h>

#include <memory>
#include <numeric>
#include <random>

namespace {
using namespace fapcast;

constexpr int kRecordings = 1400, kPhonesPerRecording = 30, kK = 17;
constexpr int kClasses = static_cast<int>(kVisemeClassCount);

VisemeClass V(int i) { return static_cast<VisemeClass>(i); }
constexpr int kFramesPerPhone = 5;  // ~83 ms at 60 fps
constexpr int kTargetPhones = 120;  // ~10 s of speech

struct World {
  std::vector<PhoneState> states;
  RowMajorMatrixXf frames;  // row-major, as a voice maps them
  std::unique_ptr<PhoneGraph> graph;
  std::vector<VisemeClass> targets;
  std::vector<TargetPhone> timing;
};

const World& world() {
  static const World w = [] {
    World w;
    std::mt19937_64 rng(42);
    std::uniform_int_distribution<int> cls(0, kClasses - 1);
    std::uint32_t f = 0;
    for (std::uint32_t u = 0; u < kRecordings; ++u)
      for (int p = 0; p < kPhonesPerRecording; ++p, f += kFramesPerPhone)
        w.states.push_back({u, V(cls(rng)), {f, kFramesPerPhone}});
    std::normal_distribution<float> normal;
    w.frames.resize(f, kK);
    for (Eigen::Index i = 0; i < w.frames.size(); ++i) w.frames.data()[i] = normal(rng);
    w.graph = std::make_unique<PhoneGraph>(w.states, join_features(w.states, w.frames));
    std::int64_t t = 0;
    for (int n = 0; n < kTargetPhones; ++n) {
      w.targets.push_back(V(cls(rng)));
      w.timing.push_back({w.targets.back(), t, t + kFramesPerPhone, false});
      t += kFramesPerPhone;
    }
    return w;
  }();
  return w;
}

void report(benchmark::State& state, const SearchResult& r) {
  const double seconds_of_animation = kTargetPhones * kFramesPerPhone / 60.0;
  state.counters["anim_s_per_cpu_s"] =
      benchmark::Counter(seconds_of_animation * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  const auto& a = r.stats.active_per_step;
  state.counters["active_mean"] = std::accumulate(a.begin(), a.end(), 0.0) / static_cast<double>(a.size());
  state.counters["units"] = static_cast<double>(r.units.size());
}

void BM_Search(benchmark::State& state) {
  const World& w = world();
  const double beta = static_cast<double>(state.range(0)) / 100.0;
  const std::optional<std::size_t> cap =
      state.range(1) > 0 ? std::optional<std::size_t>(static_cast<std::size_t>(state.range(1))) : std::nullopt;
  SearchResult r;
  for (auto _ : state) {
    r = unit_search(*w.graph, w.targets, {beta, cap, state.range(2) != 0});
    benchmark::DoNotOptimize(r.cost);
  }
  report(state, r);
}
// Args: beta x 100, cap (0 = none), prune joins (1) or evaluate every join (0: the reference).
BENCHMARK(BM_Search)
    ->ArgNames({"beta100", "cap", "prune"})
    ->Args({0, 0, 1})
    ->Args({10, 0, 0})->Args({10, 0, 1})
    ->Args({10, 64, 0})->Args({10, 64, 1})
    ->Args({10, 16, 0})->Args({10, 16, 1})
    ->Unit(benchmark::kMillisecond);

void BM_SearchAndConcatenate(benchmark::State& state) {
  const World& w = world();
  SearchResult r;
  for (auto _ : state) {
    r = unit_search(*w.graph, w.targets, {0.1, 64});
    auto y = concatenate_units(*w.graph, w.frames, r, w.timing);
    benchmark::DoNotOptimize(y.data());
  }
  report(state, r);
}
BENCHMARK(BM_SearchAndConcatenate)->Unit(benchmark::kMillisecond);

// What opening a voice pays for the search. Arg 0: the graph's indices alone; 1: the join
// features alone (from the PCA frames); 2: both and the join bound's centres and axes (its
// points are made per diviseme on first use), i.e. what Voice::open does. The bound costs
// (2) - (1) - (0).
void BM_GraphOpen(benchmark::State& state) {
  const World& w = world();
  for (auto _ : state) {
    if (state.range(0) == 0) {
      PhoneGraph g(w.states);
      benchmark::DoNotOptimize(g.size());
    } else if (state.range(0) == 1) {
      JoinFeatures f = join_features(w.states, w.frames);
      benchmark::DoNotOptimize(f.entry.data());
    } else {
      PhoneGraph g(w.states, join_features(w.states, w.frames));
      benchmark::DoNotOptimize(g.size());
    }
  }
}
BENCHMARK(BM_GraphOpen)->ArgName("what")->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// A one-sentence `fapcast say`: open the graph, then one 10 s search at the default (beta 0.1,
// cap 64), which makes the bound's points of the divisemes it joins into. Arg: prune joins (1)
// or evaluate every join (0: the reference, which never makes the points).
void BM_OpenAndSearchOnce(benchmark::State& state) {
  const World& w = world();
  // Fixed malloc thresholds: the graph's 13 MB of join features are then reused from one
  // iteration to the next, not returned to the kernel and faulted in again, which glibc's
  // dynamic thresholds do or not depending on the allocation order of the code measured.
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  SearchResult r;
  for (auto _ : state) {
    PhoneGraph g(w.states, join_features(w.states, w.frames));
    r = unit_search(g, w.targets, {0.1, 64, state.range(0) != 0});
    benchmark::DoNotOptimize(r.cost);
  }
  report(state, r);
}
BENCHMARK(BM_OpenAndSearchOnce)->ArgName("prune")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
