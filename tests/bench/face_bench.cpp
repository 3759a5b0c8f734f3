// Face-model speed: blending the full ICT mesh (sparse deltas vs a dense delta matrix), marker
// extraction, coarticulation and head-pose removal, in frames per second (items_per_second).
#include <benchmark/benchmark.h>

#include "fapcast/talker/capture_imperfections.hpp"
#include "fapcast/talker/coarticulation.hpp"
#include "fapcast/capture/head_pose.hpp"
#include "fapcast/face/marker_map.hpp"
#include "fapcast/talker/talker_markers.hpp"

namespace {

using namespace fapcast;

PhoneTimeline sentence() {  // "a pup strewn on the beach" at 22050 Hz, ~1.5 s
  const std::vector<std::pair<const char*, int>> phones{
      {"sil", 150}, {"AH0", 70}, {"P", 70}, {"AH1", 100}, {"P", 80}, {"S", 90}, {"T", 50},
      {"R", 60},    {"UW1", 180}, {"N", 80}, {"AA1", 120}, {"N", 60}, {"DH", 40}, {"AH0", 60},
      {"B", 70},    {"IY1", 150}, {"CH", 110}, {"sil", 150}};
  PhoneTimeline t{SampleRate{22050}, {}};
  std::int64_t at = 0;
  for (const auto& [p, ms] : phones) {
    t.phones.push_back({parse_arpabet(p, "bench").phone, at, at + std::int64_t{ms} * 22050 / 1000});
    at = t.phones.back().end_sample;
  }
  return t;
}

// Speech-like weights: the shapes the articulation map drives, mid-utterance.
std::vector<float> speech_weights() {
  const auto& face = ict_face_model();
  const ShapeMapper mapper(face);
  return mapper(channel_values_at(sentence(), 0.9));
}

void BM_BlendSparse(benchmark::State& state) {
  const auto& face = ict_face_model();
  std::vector<float> w = speech_weights();
  if (state.range(0) == 1) std::fill(w.begin(), w.end(), 0.3f);  // all 53 shapes on
  for (auto _ : state) benchmark::DoNotOptimize(blend(face.neutral_cm, face.expressions, w));
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(state.range(0) == 1 ? "all 53 shapes" : "speech shapes");
}
BENCHMARK(BM_BlendSparse)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The obvious alternative: a dense 3N x K delta matrix times the weight vector.
void BM_BlendDense(benchmark::State& state) {
  const auto& face = ict_face_model();
  const Eigen::Index n = face.vertex_count();
  Eigen::MatrixXf dense = Eigen::MatrixXf::Zero(3 * n, static_cast<Eigen::Index>(face.expressions.size()));
  for (std::size_t k = 0; k < face.expressions.size(); ++k) {
    const auto& d = face.expressions[k];
    for (std::size_t j = 0; j < d.vertices.size(); ++j)
      dense.block<3, 1>(3 * d.vertices[j], static_cast<Eigen::Index>(k)) = d.offsets_cm.col(static_cast<Eigen::Index>(j));
  }
  const Eigen::Map<const Eigen::VectorXf> neutral(face.neutral_cm.data(), 3 * n);
  std::vector<float> w = speech_weights();
  if (state.range(0) == 1) std::fill(w.begin(), w.end(), 0.3f);
  const Eigen::Map<const Eigen::VectorXf> weights(w.data(), static_cast<Eigen::Index>(w.size()));
  for (auto _ : state) {
    Eigen::VectorXf mesh = neutral + dense * weights;
    benchmark::DoNotOptimize(mesh.data());
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(state.range(0) == 1 ? "all 53 shapes" : "speech shapes");
}
BENCHMARK(BM_BlendDense)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// Full-mesh blend then picking the 39 marker vertices (what a mesh-based capture would do).
void BM_MarkersViaFullMesh(benchmark::State& state) {
  const auto& face = ict_face_model();
  const auto vertices = marker_vertices();
  const std::vector<float> w = speech_weights();
  for (auto _ : state)
    benchmark::DoNotOptimize(marker_positions(blend(face.neutral_cm, face.expressions, w), vertices));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MarkersViaFullMesh)->Unit(benchmark::kMicrosecond);

// The talker's path: the blend restricted to the marker vertices.
void BM_MarkersViaMarkerBlender(benchmark::State& state) {
  const auto& face = ict_face_model();
  const auto vertices = marker_vertices();
  const MarkerBlender blender(face, vertices);
  const std::vector<float> w = speech_weights();
  for (auto _ : state) benchmark::DoNotOptimize(blender(w));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MarkersViaMarkerBlender);

// Timeline -> channel tracks -> shape weights -> markers, per 60 fps frame.
void BM_TalkerMarkers(benchmark::State& state) {
  const auto& face = ict_face_model();
  const PhoneTimeline t = sentence();
  std::int64_t frames = 0;
  for (auto _ : state) {
    const MarkerFrames<Centimetres> take = talker_markers(face, t);
    frames += take.frame_count();
    benchmark::DoNotOptimize(take.positions.data());
  }
  state.SetItemsProcessed(frames);
}
BENCHMARK(BM_TalkerMarkers)->Unit(benchmark::kMillisecond);

void BM_HeadPoseRemoval(benchmark::State& state) {
  MarkerFrames<Centimetres> take = talker_markers(ict_face_model(), sentence());
  const auto rigid = rigid_marker_rows();
  const Eigen::Matrix3Xd reference = rigid_reference(take, rigid, 0);
  PortableRandom random(1);
  apply_head_motion(take, HeadMotion(random));
  add_marker_noise(take, random);
  for (auto _ : state) benchmark::DoNotOptimize(remove_head_pose(take, rigid, reference));
  state.SetItemsProcessed(state.iterations() * take.frame_count());
}
BENCHMARK(BM_HeadPoseRemoval)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
