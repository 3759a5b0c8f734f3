// Synthesis speed without TTS: timed phones of a 10-second sentence -> 60 fps PCA frames and
// tongue (synthesize: grid, search, warp, cross-fade, smoothing, tongue), then FAPs
// (pca_to_faps) at 25 fps. The graph has the paper corpus's size (1,400 recordings x 30
// phones, 21 classes, k = 17, 5 frames per phone) with SYNTHETIC class shapes plus noise: a
// stand-in for a voice's search data, not a voice. Counters: seconds of animation per CPU second,
// mean active states per phone. Baselines in the same run: no cap on the active states, and
// PCA -> FAP through the whole mesh (mean + c * components over 3N columns) instead of the basis
// restricted to the feature points. The jaw term of the search against the same synthesis
// without it, and the cost of making its guide from a voice of the default voice's size.
#include "fapcast/codec/face_geometry.hpp"
#include "fapcast/codec/pca_faps.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/synthesis/jaw_guide.hpp"
#include "fapcast/synthesis/synthesis.hpp"
#include "fapcast/synthesis/tongue.hpp"
#include "fapcast/transport/track_resample.hpp"
#include "support/synthetic_voice_graph.hpp"
#include "support/tiny_voice.hpp"

#include <benchmark/benchmark.h>
#include <malloc.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <optional>
#include <random>

namespace {
using namespace fapcast;

constexpr std::int64_t kRate = 22050;
constexpr SampleRate kSampleRate{kRate};
constexpr double kSentenceS = 10.0;
constexpr Eigen::Index kK = 17;
constexpr std::int64_t kMeshVertices = 26'719;  // ICT-FaceKit's full head, for the mesh baseline

struct World {
  test::SyntheticVoiceGraph voice;
  std::vector<TimedPhone> phones;
  FeaturePointBasis basis;
  RowMajorMatrixXf mesh_mean, mesh_components;
  std::vector<FeaturePointVertex> fp_vertices;
};

const World& world() {
  static const World w = [] {
    World w;
    w.voice = test::synthetic_voice_graph(1400, 30, 5, kK, 42, 0.1f);
    // A 10 s sentence: random phones of 50..130 ms, silence at both ends.
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int> phone(0, static_cast<int>(kPhoneCount) - 2), ms(50, 130);
    std::int64_t at = 0;
    const auto end = static_cast<std::int64_t>(kSentenceS * kRate);
    while (at < end) {
      const std::int64_t len = std::min<std::int64_t>(end - at, ms(rng) * kRate / 1000);
      const auto p = (at == 0 || at + len >= end) ? Phone::SIL : static_cast<Phone>(phone(rng));
      w.phones.push_back({p, at, at + len});
      at += len;
    }
    // A mesh basis whose feature-point vertices sit on the generic face (cm).
    const auto face = generic_adult_face();
    std::normal_distribution<float> normal(0.0f, 0.05f);
    w.mesh_mean = RowMajorMatrixXf::Zero(1, 3 * kMeshVertices);
    w.mesh_components.resize(kK, 3 * kMeshVertices);
    for (Eigen::Index i = 0; i < w.mesh_components.size(); ++i) w.mesh_components.data()[i] = normal(rng);
    std::int64_t v = 0;
    for (const auto& [fp, at3] : face.feature_points) {
      w.fp_vertices.push_back({fp, v * 997});
      for (int a = 0; a < 3; ++a) w.mesh_mean(0, 3 * v * 997 + a) = static_cast<float>(at3(a));
      ++v;
    }
    w.basis = restrict_basis(w.mesh_mean, w.mesh_components, w.fp_vertices, face.feature_points);
    return w;
  }();
  return w;
}

void report(benchmark::State& state, const SynthesizedTrack& s) {
  state.counters["anim_s_per_cpu_s"] =
      benchmark::Counter(kSentenceS * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  const auto& a = s.search.stats.active_per_step;
  state.counters["active_mean"] = std::accumulate(a.begin(), a.end(), 0.0) / static_cast<double>(a.size());
  state.counters["active_max"] = static_cast<double>(*std::max_element(a.begin(), a.end()));
  state.counters["phones"] = static_cast<double>(s.timeline.phones.size());
  state.counters["units"] = static_cast<double>(s.search.units.size());
}

SynthesisOptions options_of(const benchmark::State& state) {
  SynthesisOptions o;
  o.search.beta = static_cast<double>(state.range(0)) / 100.0;
  o.search.max_active = state.range(1) > 0 ? std::optional<std::size_t>(state.range(1)) : std::nullopt;
  o.search.prune_joins = state.range(2) != 0;
  return o;
}

// Phones -> 60 fps PCA frames and tongue. Args: beta x 100, cap (0 = none), prune joins (1) or
// evaluate every join (0: the reference search, identical results).
void BM_Synthesize(benchmark::State& state) {
  const World& w = world();
  const auto options = options_of(state);
  SynthesizedTrack s;
  for (auto _ : state) {
    s = synthesize(*w.voice.graph, w.voice.frames, w.phones, kSampleRate, 0, options);
    benchmark::DoNotOptimize(s.pca_frames.data());
  }
  report(state, s);
}
BENCHMARK(BM_Synthesize)
    ->ArgNames({"beta100", "cap", "prune"})
    ->Args({0, 0, 1})->Args({0, 16, 1})
    ->Args({10, 0, 0})->Args({10, 0, 1})
    ->Args({10, 64, 0})->Args({10, 64, 1})  // the `say` default
    ->Args({10, 16, 0})->Args({10, 16, 1})
    ->Unit(benchmark::kMillisecond);

// The unit search alone of BM_Synthesize: the same graph and the same 114 target classes (read
// off the states its search chose, so after any substitution).
void BM_SearchOnly(benchmark::State& state) {
  const World& w = world();
  const auto options = options_of(state);
  const auto track = synthesize(*w.voice.graph, w.voice.frames, w.phones, kSampleRate, 0, options);
  std::vector<VisemeClass> targets;
  for (const StateId j : track.search.states) targets.push_back(w.voice.graph->state(j).viseme);
  SynthesizedTrack s;
  for (auto _ : state) {
    s.search = unit_search(*w.voice.graph, targets, options.search);
    benchmark::DoNotOptimize(s.search.cost);
  }
  s.timeline = track.timeline;
  report(state, s);
}
BENCHMARK(BM_SearchOnly)
    ->ArgNames({"beta100", "cap", "prune"})
    ->Args({0, 0, 1})->Args({10, 0, 0})->Args({10, 0, 1})
    ->Args({10, 64, 0})->Args({10, 64, 1})->Args({10, 16, 1})
    ->Unit(benchmark::kMillisecond);

// A one-sentence `fapcast say` as far as the search goes: open the graph (indices, join
// features, the bound's centres and axes), then one search of the same 114 targets, which makes
// the bound's tables of the divisemes it joins into. Arg: prune joins (1) or the reference (0).
void BM_OpenAndSearchOnce(benchmark::State& state) {
  const World& w = world();
  // Fixed malloc thresholds: the graph's 13 MB of join features are then reused from one
  // iteration to the next, not returned to the kernel and faulted in again, which glibc's
  // dynamic thresholds do or not depending on the allocation order of the code measured.
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  const auto track = synthesize(*w.voice.graph, w.voice.frames, w.phones, kSampleRate, 0, {});
  std::vector<VisemeClass> targets;
  for (const StateId j : track.search.states) targets.push_back(w.voice.graph->state(j).viseme);
  SynthesizedTrack s;
  for (auto _ : state) {
    const PhoneGraph graph(w.voice.states, join_features(w.voice.states, w.voice.frames));
    s.search = unit_search(graph, targets, {0.1, 64, state.range(0) != 0});
    benchmark::DoNotOptimize(s.search.cost);
  }
  s.timeline = track.timeline;
  report(state, s);
}
BENCHMARK(BM_OpenAndSearchOnce)->ArgName("prune")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Phones -> FAP frames at 25 fps (what `say` writes, without TTS and file output).
void BM_PhonesToFaps(benchmark::State& state) {
  const World& w = world();
  const auto options = options_of(state);
  SynthesizedTrack s;
  for (auto _ : state) {
    s = synthesize(*w.voice.graph, w.voice.frames, w.phones, kSampleRate, 0, options);
    FapSequence seq{"bench", {60, 1}, pca_to_faps(s.pca_frames, w.basis)};
    auto out = resample_track(seq, {25, 1}, ResampleMode::kLinear);
    benchmark::DoNotOptimize(out.frames.data());
  }
  report(state, s);
}
BENCHMARK(BM_PhonesToFaps)
    ->ArgNames({"beta100", "cap", "prune"})
    ->Args({0, 0, 1})->Args({10, 64, 0})->Args({10, 64, 1})->Args({10, 16, 1})
    ->Unit(benchmark::kMillisecond);

// The work after the search, at the `say` default, from one fixed search result: what
// synthesize() does besides unit_search (voice grid, concatenation: warp, cross-fade, smoothing; tongue)
// and what follows it (PCA -> FAPs at 60 fps, resampled to 25 fps). Together they are
// BM_PhonesToFaps minus the search.
const SynthesizedTrack& default_track() {
  static const SynthesizedTrack s = [] {
    const World& w = world();
    const SynthesisOptions o;  // the shipped defaults: beta 0.1, cap 64
    return synthesize(*w.voice.graph, w.voice.frames, w.phones, kSampleRate, 0, o);
  }();
  return s;
}

void BM_AfterSearch(benchmark::State& state) {
  const World& w = world();
  const SynthesizedTrack& s = default_track();
  for (auto _ : state) {
    // The bench graph covers every class, so the covered targets are the timeline's own.
    const auto timeline = place_on_voice_grid(w.phones, kSampleRate);
    auto pca = concatenate_units(*w.voice.graph, w.voice.frames, s.search, timeline.phones);
    auto tongue = tongue_track(timeline.phones, timeline.phone_of);
    benchmark::DoNotOptimize(pca.data());
    benchmark::DoNotOptimize(tongue.data());
  }
  state.counters["anim_s_per_cpu_s"] =
      benchmark::Counter(kSentenceS * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_AfterSearch)->Unit(benchmark::kMillisecond);

void BM_FapsAt25(benchmark::State& state) {
  const World& w = world();
  const SynthesizedTrack& s = default_track();
  for (auto _ : state) {
    FapSequence seq{"bench", {60, 1}, pca_to_faps(s.pca_frames, w.basis)};
    auto out = resample_track(seq, {25, 1}, ResampleMode::kLinear);
    benchmark::DoNotOptimize(out.frames.data());
  }
  state.counters["anim_s_per_cpu_s"] =
      benchmark::Counter(kSentenceS * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FapsAt25)->Unit(benchmark::kMillisecond);

// A jaw guide of random openings and a random move for the benchmark's graph (SYNTHETIC: the
// graph is no voice).
JawGuide random_guide() {
  const World& w = world();
  std::mt19937_64 rng(11);
  std::normal_distribution<float> normal;
  JawGuide guide;
  guide.state_opening.resize(w.voice.graph->size());
  for (float& a : guide.state_opening) a = normal(rng);
  for (float& a : guide.phone_opening) a = normal(rng);
  guide.spread_mm = 1.0;
  guide.chin_drop.resize(static_cast<std::size_t>(w.voice.frames.cols()));
  guide.jaw_move.resize(guide.chin_drop.size());
  for (float& a : guide.chin_drop) a = 0.001f * normal(rng);
  for (float& a : guide.jaw_move) a = 0.001f * normal(rng);
  return guide;
}

// The benchmark's sentence synthesised with `options` and `guide`, reported.
void synthesize_with_guide(benchmark::State& state, const SynthesisOptions& options, const JawGuide& guide) {
  const World& w = world();
  SynthesizedTrack s;
  for (auto _ : state) {
    s = synthesize(*w.voice.graph, w.voice.frames, w.phones, kSampleRate, 0, options, "bench", &guide);
    benchmark::DoNotOptimize(s.pca_frames.data());
  }
  report(state, s);
}

// The jaw term (spec/search.md) against the same synthesis without it, in one run: the `say`
// default with a guide of random openings (SYNTHETIC: the graph is no voice), Arg 1 = on at
// weight 0.1, 0 = off. What it adds is the wanted openings (low-pass over the sentence's frames)
// and one more term per offered state.
void BM_Synthesize_JawTerm(benchmark::State& state) {
  SynthesisOptions options;
  options.search.jaw_weight = state.range(0) != 0 ? 0.1 : 0.0;
  synthesize_with_guide(state, options, random_guide());
}
BENCHMARK(BM_Synthesize_JawTerm)->ArgName("jaw")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The jaw's level (jaw_level.hpp) on the same sentence, Arg 1 = level 1, 0 = off: each frame's
// opening, two low-passes over the sentence and one move per frame, after the search.
void BM_Synthesize_JawLevel(benchmark::State& state) {
  SynthesisOptions options;
  options.jaw_level = state.range(0) != 0 ? 1.0 : 0.0;
  synthesize_with_guide(state, options, random_guide());
}
BENCHMARK(BM_Synthesize_JawLevel)->ArgName("level")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Making the guide from a voice the size of the default one (66,132 frames, k = 17, 6,921 phone
// states, SYNTHETIC values): done once per command when the term is on.
void BM_MakeJawGuide_DefaultVoiceSize(benchmark::State& state) {
  static const std::filesystem::path file = [] {
    constexpr std::uint32_t kFrames = 66'132, kStates = 6'921;
    test::TinyVoice t;
    t.vertices = 8;  // the guide reads one column of the components: the mesh's size does not matter
    t.components = kK;
    std::mt19937_64 rng(5);
    std::normal_distribution<float> normal;
    t.coefficients = RowMajorMatrixXf(kFrames, kK);
    for (Eigen::Index i = 0; i < t.coefficients.size(); ++i) t.coefficients.data()[i] = normal(rng);
    t.graph.utterances = {{0, kFrames}};
    t.graph.frame_count = kFrames;
    t.graph.states.clear();
    t.graph.phones.clear();
    for (std::uint32_t j = 0, at = 0; j < kStates; ++j) {
      const std::uint32_t n = j + 1 < kStates ? kFrames / kStates : kFrames - at;
      const auto phone = static_cast<Phone>(j % kPhoneCount);
      t.graph.states.push_back({0, search_viseme(phone), {at, n}});
      t.graph.phones.push_back(phone);
      at += n;
    }
    t.feature_points = voice_feature_points_json(
        std::vector<VoiceFeaturePoint>{{"2.1", 0, {0.0, -0.06, 0.08}}},
        std::vector<VoiceRigidMarker>{{"H.temple_l", 1, {0.07, 0.03, 0.0}, {0.07, 0.03, 0.01}},
                                      {"H.temple_r", 2, {-0.07, 0.03, 0.0}, {-0.07, 0.03, 0.01}},
                                      {"H.nose_bridge", 3, {0.0, 0.04, 0.09}, {0.0, 0.04, 0.1}}});
    const auto path = std::filesystem::temp_directory_path() / "fapcast_synthesis_bench_voice.fapv";
    write_file_atomically(path, t.bytes());
    return path;
  }();
  const Voice voice = Voice::open(file);
  for (auto _ : state) benchmark::DoNotOptimize(make_jaw_guide(voice).spread_mm);
}
BENCHMARK(BM_MakeJawGuide_DefaultVoiceSize)->Unit(benchmark::kMillisecond);

// The search is over the whole utterance (Viterbi back-trace), so the first frame exists only
// when the sentence is synthesised: time to first frame = synthesis + one frame of FAPs.
void BM_TimeToFirstFrame(benchmark::State& state) {
  const World& w = world();
  const auto options = options_of(state);
  for (auto _ : state) {
    auto s = synthesize(*w.voice.graph, w.voice.frames, w.phones, kSampleRate, 0, options);
    auto first = pca_to_faps(s.pca_frames.topRows(1), w.basis);
    benchmark::DoNotOptimize(first.data());
  }
}
BENCHMARK(BM_TimeToFirstFrame)
    ->ArgNames({"beta100", "cap", "prune"})
    ->Args({0, 0, 1})->Args({10, 64, 0})->Args({10, 64, 1})->Args({10, 16, 1})
    ->Unit(benchmark::kMillisecond);

// PCA -> FAP for 600 frames (10 s at 60 fps): the restricted basis against reconstructing every
// mesh vertex and then reading the feature points.
Eigen::MatrixXf frames_600() {
  std::mt19937_64 rng(3);
  std::normal_distribution<float> normal;
  Eigen::MatrixXf c(600, kK);
  for (Eigen::Index i = 0; i < c.size(); ++i) c.data()[i] = normal(rng);
  return c;
}

void BM_PcaToFaps_RestrictedBasis(benchmark::State& state) {
  const World& w = world();
  const Eigen::MatrixXf c = frames_600();
  for (auto _ : state) {
    auto f = pca_to_faps(c, w.basis);
    benchmark::DoNotOptimize(f.data());
  }
  state.counters["frames_per_s"] = benchmark::Counter(600.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PcaToFaps_RestrictedBasis)->Unit(benchmark::kMillisecond);

void BM_PcaToFaps_FullMesh(benchmark::State& state) {
  const World& w = world();
  const Eigen::MatrixXf c = frames_600();
  // Each frame reconstructed over all 3N columns, then the feature points read off it (the FAP
  // arithmetic that follows is left out: this baseline is a lower bound).
  for (auto _ : state) {
    RowMajorMatrixXf mesh(1, w.mesh_mean.cols());
    Eigen::MatrixXf picked(600, static_cast<Eigen::Index>(3 * w.fp_vertices.size()));
    for (Eigen::Index n = 0; n < 600; ++n) {
      mesh.noalias() = w.mesh_mean + c.row(n) * w.mesh_components;
      for (std::size_t i = 0; i < w.fp_vertices.size(); ++i)
        for (int a = 0; a < 3; ++a)
          picked(n, static_cast<Eigen::Index>(3 * i + a)) = mesh(0, 3 * w.fp_vertices[i].vertex + a);
    }
    benchmark::DoNotOptimize(picked.data());
  }
  state.counters["frames_per_s"] = benchmark::Counter(600.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PcaToFaps_FullMesh)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
