// Mesh outputs and model adaptation on the full ICT face (26,719 vertices, 52,220 triangles):
//  - building a FaceAdaptation (OpenMesh adjacency) vs the obvious alternative, a plain scatter of
//    triangle maps onto their corners with no mesh structure: time and peak heap;
//  - adapting one dense 3 x N target, and all 53 ICT expression targets (sparse);
//  - .glb bytes per second of animation for k = 17 morph targets at 60 fps;
//  - `voice adapt` (adapt_voice) of a voice shaped like the reference voice (k = 17, 21 RBF
//    centres, full ICT face) to the actor, against opening (mapping + verifying) the same voice;
//  - the face basis `say` makes of that voice's PCA components, read in place against copied.
// Peak heap is counted by replacing global operator new/delete in this program only.
#include <benchmark/benchmark.h>

#include <malloc.h>

#include <Eigen/Geometry>
#include <atomic>
#include <cstdlib>
#include <new>

#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/face/face_adaptation.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/obj_mesh.hpp"
#include "fapcast/voice/voice_adaptation.hpp"
#include "fapcast/utterance/voice_face.hpp"
#include "fapcast/core/file_io.hpp"
#include "support/scatter_adaptation.hpp"
#include "support/tiny_voice.hpp"

#include <filesystem>

namespace {
std::atomic<std::int64_t> g_heap{0}, g_peak{0};
void* counted_alloc(std::size_t n) {
  void* p = std::malloc(n == 0 ? 1 : n);
  if (!p) throw std::bad_alloc();
  const auto now = g_heap += static_cast<std::int64_t>(malloc_usable_size(p));
  auto peak = g_peak.load();
  while (now > peak && !g_peak.compare_exchange_weak(peak, now)) {}
  return p;
}
void counted_free(void* p) {
  if (!p) return;
  g_heap -= static_cast<std::int64_t>(malloc_usable_size(p));
  std::free(p);
}
}  // namespace

void* operator new(std::size_t n) { return counted_alloc(n); }
void* operator new[](std::size_t n) { return counted_alloc(n); }
void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_free(p); }

namespace {

using namespace fapcast;

const FaceModel& actor() {
  static const FaceModel a = make_actor(ict_face_model(), std::vector<float>{0.8f, -0.6f, 0.5f, 0.0f, 0.7f});
  return a;
}

template <typename Build>
void measure_build(benchmark::State& state, Build build) {
  const auto& g = ict_face_model();
  std::int64_t peak = 0;
  for (auto _ : state) {
    const auto before = g_heap.load();
    g_peak = before;
    auto result = build(g, actor());
    benchmark::DoNotOptimize(result);
    peak = std::max(peak, g_peak.load() - before);
  }
  state.counters["peak_heap_MB"] = static_cast<double>(peak) / 1e6;
  state.counters["vertices"] = static_cast<double>(g.vertex_count());
}

void BM_AdaptationBuild_OpenMesh(benchmark::State& state) {
  measure_build(state, [](const FaceModel& g, const FaceModel& a) {
    return FaceAdaptation(g.neutral_cm, a.neutral_cm, g.faces);
  });
  const FaceAdaptation held(ict_face_model().neutral_cm, actor().neutral_cm, ict_face_model().faces);
  state.counters["held_MB"] = static_cast<double>(held.memory_bytes()) / 1e6;
}
BENCHMARK(BM_AdaptationBuild_OpenMesh)->Unit(benchmark::kMillisecond);

void BM_AdaptationBuild_Scatter(benchmark::State& state) {
  measure_build(state, [](const FaceModel& g, const FaceModel& a) {
    return test::scatter_adaptation_maps(g.neutral_cm, a.neutral_cm, g.faces);
  });
}
BENCHMARK(BM_AdaptationBuild_Scatter)->Unit(benchmark::kMillisecond);

void BM_AdaptDenseTarget(benchmark::State& state) {
  const auto& g = ict_face_model();
  const FaceAdaptation adaptation(g.neutral_cm, actor().neutral_cm, g.faces);
  Positions d = Positions::Zero(3, g.vertex_count());
  add_scaled(d, g.expressions[g.expression_index("jawOpen")], 1.0f);
  for (auto _ : state) benchmark::DoNotOptimize(adaptation.adapt(d));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AdaptDenseTarget)->Unit(benchmark::kMicrosecond);

void BM_AdaptAll53SparseTargets(benchmark::State& state) {
  const auto& g = ict_face_model();
  const FaceAdaptation adaptation(g.neutral_cm, actor().neutral_cm, g.faces);
  for (auto _ : state)
    for (const auto& e : g.expressions) benchmark::DoNotOptimize(adaptation.adapt(e));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(g.expressions.size()));
}
BENCHMARK(BM_AdaptAll53SparseTargets)->Unit(benchmark::kMillisecond);

// .glb of the ICT face with k = 17 targets and `seconds` of 60 fps weights.
MorphAnimation ict_animation(int seconds) {
  const auto& g = ict_face_model();
  MorphAnimation a;
  a.base_positions_m = 0.01f * g.neutral_cm;
  a.triangles = triangulate(g.faces);
  for (int k = 0; k < 17; ++k) {
    Positions d = Positions::Zero(3, g.vertex_count());
    add_scaled(d, g.expressions[static_cast<std::size_t>(k) * 3], 0.01f);
    a.targets_m.push_back(d);
  }
  a.weights = Eigen::MatrixXf::Random(60 * seconds, 17);
  a.rate = {60, 1};
  return a;
}

void BM_GlbWrite_k17_60fps(benchmark::State& state) {
  const auto seconds = static_cast<int>(state.range(0));
  const auto a = ict_animation(seconds);
  std::size_t bytes = 0;
  for (auto _ : state) bytes = write_glb(a).size();
  const auto one = write_glb(ict_animation(1)).size();
  const auto eleven = write_glb(ict_animation(11)).size();
  state.counters["glb_MB"] = static_cast<double>(bytes) / 1e6;
  state.counters["animation_bytes_per_s"] = static_cast<double>(eleven - one) / 10.0;
  state.counters["mesh_and_targets_MB"] = static_cast<double>(one - (eleven - one) / 10) / 1e6;
}
BENCHMARK(BM_GlbWrite_k17_60fps)->Arg(10)->Unit(benchmark::kMillisecond);

// A voice file shaped like the reference voice (k = 17, m = 21, D = 3 x 26,719) with SYNTHETIC
// contents: what adapt_voice reads and writes is independent of the values.
const std::filesystem::path& reference_shaped_voice() {
  static const std::filesystem::path file = [] {
    test::TinyVoice t;
    t.vertices = ict_face_model().vertex_count();
    t.components = 17;
    t.centres = 21;
    t.coefficients = RowMajorMatrixXf::Zero(3, 17);
    t.set_neutral_face(0.01f * ict_face_model().neutral_cm);  // retarget checks the generic face
    const auto path = std::filesystem::temp_directory_path() / "fapcast_mesh_bench_voice.fapv";
    write_file_atomically(path, t.bytes());
    return path;
  }();
  return file;
}

void BM_VoiceAdaptation_k17(benchmark::State& state) {
  const Voice voice = Voice::open(reference_shaped_voice());
  const auto& g = ict_face_model();
  const Positions generic_m = 0.01f * g.neutral_cm, specific_m = 0.01f * actor().neutral_cm;
  std::int64_t peak = 0;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto before = g_heap.load();
    g_peak = before;
    const auto out = adapt_voice(voice, generic_m, specific_m, g.faces, "actor");
    bytes = out.bytes.size();
    peak = std::max(peak, g_peak.load() - before);
  }
  state.counters["peak_heap_MB"] = static_cast<double>(peak) / 1e6;
  state.counters["voice_MB"] = static_cast<double>(bytes) / 1e6;
}
BENCHMARK(BM_VoiceAdaptation_k17)->Unit(benchmark::kMillisecond);

void BM_VoiceOpen_k17(benchmark::State& state) {
  const auto& file = reference_shaped_voice();
  for (auto _ : state) benchmark::DoNotOptimize(Voice::open(file).dimension());
}
BENCHMARK(BM_VoiceOpen_k17)->Unit(benchmark::kMillisecond);

// The face basis `say` makes on every run, from the k x D PCA components (5.45 MB here, as in
// the reference voice): read in place in the mapped voice (SpeechBasis, what `say` does) against
// the obvious alternative, the components copied out of the file first (what it did before).
// Both restrict the same basis to the feature points (face_basis); the copy's page faults count.
void BM_FaceBasisFromVoiceView_k17(benchmark::State& state) {
  const Voice voice = Voice::open(reference_shaped_voice());
  for (auto _ : state) {
    const SpeechBasis speech(voice);
    benchmark::DoNotOptimize(face_basis(speech, voice, "bench").components.data());
  }
  state.counters["components_MB"] = static_cast<double>(voice.pca_components().size() * sizeof(float)) / 1e6;
}
BENCHMARK(BM_FaceBasisFromVoiceView_k17)->Unit(benchmark::kMicrosecond);

void BM_FaceBasisFromCopy_k17(benchmark::State& state) {
  const Voice voice = Voice::open(reference_shaped_voice());
  std::vector<FeaturePointVertex> vertices;
  FeaturePointPositions neutral;
  for (const VoiceFeaturePoint& p : voice.feature_points()) {
    vertices.push_back({*parse_feature_point(p.label), p.vertex});
    neutral[vertices.back().fp] = p.neutral_m;
  }
  for (auto _ : state) {
    const RowMajorMatrixXf mean = voice.pca_mean();
    const RowMajorMatrixXf components = voice.pca_components();
    benchmark::DoNotOptimize(restrict_basis(mean, components, vertices, neutral).components.data());
  }
  state.counters["components_MB"] = static_cast<double>(voice.pca_components().size() * sizeof(float)) / 1e6;
}
BENCHMARK(BM_FaceBasisFromCopy_k17)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
