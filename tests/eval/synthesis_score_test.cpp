// Scoring synthesised tracks against recorded ones on the target face.
#include "fapcast/eval/synthesis_score.hpp"

#include "fapcast/face/marker_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace fapcast {
namespace {

// Every feature point of the marker table (the rigid H.* markers excluded), with its vertex.
struct FeaturePoints {
  std::vector<std::string> labels;
  std::vector<std::int32_t> vertices;
};

FeaturePoints feature_points() {
  FeaturePoints f;
  for (const auto& s : marker_sites())
    if (s.role != MarkerRole::rigid) f.labels.emplace_back(s.label), f.vertices.push_back(s.vertex);
  return f;
}

TEST(EvaluationPoints, FindsTheLipsAndTheTemples) {
  const auto f = feature_points();
  const auto p = evaluation_points(f.labels, f.vertices);
  EXPECT_EQ(p.vertices.size(), f.vertices.size() + 2);
  EXPECT_EQ(p.feature_points.size(), f.vertices.size());
  EXPECT_EQ(p.lip_points.size(), 16u) << "inner lip 2.2-2.9 and outer lip 8.1-8.8";
  ASSERT_TRUE(p.chin.has_value());
  EXPECT_EQ(p.labels[*p.chin], "2.1");
  for (std::size_t i = 0; i < kLipMarkerLabels.size(); ++i)
    EXPECT_EQ(p.labels[static_cast<std::size_t>(p.lip_measure[i])], kLipMarkerLabels[i]);

  auto without_81 = f;
  const auto at = std::find(without_81.labels.begin(), without_81.labels.end(), "8.1") - without_81.labels.begin();
  without_81.labels.erase(without_81.labels.begin() + at);
  without_81.vertices.erase(without_81.vertices.begin() + at);
  EXPECT_THROW(evaluation_points(without_81.labels, without_81.vertices), std::invalid_argument);
  auto twice = f;
  twice.labels[1] = twice.labels[0];
  EXPECT_THROW(evaluation_points(twice.labels, twice.vertices), std::invalid_argument);
  auto without_chin = f;
  const auto chin = std::find(without_chin.labels.begin(), without_chin.labels.end(), "2.1") - without_chin.labels.begin();
  without_chin.labels.erase(without_chin.labels.begin() + chin);
  without_chin.vertices.erase(without_chin.vertices.begin() + chin);
  EXPECT_FALSE(evaluation_points(without_chin.labels, without_chin.vertices).chin.has_value());
}

TEST(VertexTracks, PcaTracksAreTheReconstructedMeshAtTheVertices) {
  std::mt19937_64 rng(5);
  std::normal_distribution<float> normal;
  const int N = 50, k = 4, F = 7;
  RowMajorMatrixXf mean(1, 3 * N), components(k, 3 * N);
  Eigen::MatrixXf coefficients(F, k);
  for (auto* m : {&mean, &components})
    for (Eigen::Index i = 0; i < m->size(); ++i) m->data()[i] = normal(rng);
  for (Eigen::Index i = 0; i < coefficients.size(); ++i) coefficients.data()[i] = normal(rng);
  const std::vector<std::int32_t> vertices{3, 49, 0, 17};
  const Eigen::MatrixXf tracks = vertex_tracks(mean, components, coefficients, vertices);
  ASSERT_EQ(tracks.rows(), F);
  ASSERT_EQ(tracks.cols(), 12);
  const Eigen::MatrixXf mesh = (coefficients * components).rowwise() + mean.row(0);
  for (std::size_t i = 0; i < vertices.size(); ++i)
    EXPECT_LT((tracks.middleCols<3>(3 * static_cast<Eigen::Index>(i)) - mesh.middleCols<3>(3 * vertices[i])).cwiseAbs().maxCoeff(), 1e-5f);
  EXPECT_THROW(vertex_tracks(mean, components, coefficients, std::vector<std::int32_t>{50}), std::invalid_argument);
  EXPECT_THROW(vertex_tracks(mean, components, Eigen::MatrixXf(F, k + 1), vertices), std::invalid_argument);
}

TEST(VertexTracks, RbfTracksAreTheMapAtTheVertices) {
  std::mt19937_64 rng(6);
  std::normal_distribution<double> normal;
  const int m = 6, d = 9, N = 20;
  Eigen::MatrixXd centres(m, d), targets(m, 3 * N), sources(d, 5);
  for (auto* x : {&centres, &targets, &sources})
    for (Eigen::Index i = 0; i < x->size(); ++i) x->data()[i] = normal(rng);
  const RbfMap map = fit_rbf_by_gcv(centres, targets, 4.0);
  const std::vector<std::int32_t> vertices{19, 2};
  const Eigen::MatrixXf tracks = vertex_tracks(Retargeting(map), sources, vertices);
  ASSERT_EQ(tracks.rows(), 5);
  for (Eigen::Index f = 0; f < 5; ++f) {
    const Eigen::VectorXd y = map(sources.col(f));
    for (std::size_t i = 0; i < vertices.size(); ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(tracks(f, 3 * static_cast<Eigen::Index>(i) + c), y(3 * vertices[i] + c), 1e-5);
  }
  EXPECT_THROW(vertex_tracks(Retargeting(map), Eigen::MatrixXd(d + 1, 2), vertices), std::invalid_argument);

  // With a lip-contact term the tracks follow the whole retargeting, its shape included.
  LipContact contact;
  contact.shape = Eigen::VectorXd::Zero(3 * N);
  contact.shape.segment<3>(3 * 19) = Eigen::Vector3d(0.0, -0.5, 0.0);
  contact.gap_weights = Eigen::VectorXd::Zero(m);
  contact.gap_offset_m = 100.0, contact.shape_gap_m = -1.0, contact.target_contact_m = 0.0;
  contact.source_contact_m = 0.0, contact.reach_m = 1e6;  // every frame near contact
  contact.source_upper = 0, contact.source_lower = 3;
  const Retargeting whole(map, contact);
  const Eigen::MatrixXf closed = vertex_tracks(whole, sources, vertices);
  for (Eigen::Index f = 0; f < 5; ++f) {
    const Eigen::VectorXd y = whole(sources.col(f));
    EXPECT_NEAR(closed(f, 1), y(3 * 19 + 1), 1e-5);
    // the whole excess is far beyond the cap: 1.5 units of the shape moved vertex 19 down
    EXPECT_NEAR(closed(f, 1), tracks(f, 1) - 0.5 * LipContact::kMaxAmount, 1e-5);
    EXPECT_NEAR(closed(f, 4), tracks(f, 4), 1e-5);  // and left vertex 2 alone
  }
}

// Tracks of a made-up face (a point cloud of the right size), in metres, whose mouth opens and
// closes: 8.2 and 2.3 move down by up to 2 * amplitude, the chin 2.1 by `jaw` times that.
Eigen::MatrixXf talking(const EvaluationPoints& p, int frames, double amplitude_m, double jaw = 0.5) {
  Eigen::MatrixXf t(frames, 3 * static_cast<Eigen::Index>(p.vertices.size()));
  for (int n = 0; n < frames; ++n)
    for (std::size_t i = 0; i < p.vertices.size(); ++i) {
      const double a = static_cast<double>(i);
      Eigen::Vector3f x(static_cast<float>(0.03 * std::sin(a)), static_cast<float>(0.03 * std::cos(1.7 * a)),
                        static_cast<float>(0.05 + 0.01 * std::sin(2.3 * a)));
      if (p.labels[i] == "8.2" || p.labels[i] == "2.3")
        x.y() -= static_cast<float>(amplitude_m * (1.0 - std::cos(0.3 * n)));
      if (p.labels[i] == "2.1") x.y() -= static_cast<float>(jaw * amplitude_m * (1.0 - std::cos(0.3 * n)));
      t.block<1, 3>(n, 3 * static_cast<Eigen::Index>(i)) = x.transpose();
    }
  return t;
}

TEST(SynthesisScorer, PerfectAndShiftedSyntheses) {
  const auto f = feature_points();
  const auto p = evaluation_points(f.labels, f.vertices);
  const Eigen::MatrixXf recorded = talking(p, 60, 0.004);

  SynthesisScorer perfect(p);
  perfect.add(recorded, recorded);
  const auto s = perfect.score();
  EXPECT_EQ(s.frames, 60u);
  EXPECT_NEAR(s.lips.height.mean_error_percent, 0.0, 1e-9);
  EXPECT_NEAR(s.lips.height.correlation, 1.0, 1e-9);
  EXPECT_EQ(s.lip_rms_mm, 0.0);
  EXPECT_EQ(s.all_rms_mm, 0.0);
  EXPECT_EQ(s.jaw.frames, 60u);
  EXPECT_NEAR(s.jaw.correlation, 1.0, 1e-9);
  EXPECT_EQ(s.jaw.mean_abs_difference, 0.0);

  // The whole face moved 1 mm forward and 2 frames longer: RMS 1 mm, lips unchanged.
  Eigen::MatrixXf shifted = talking(p, 62, 0.004);
  for (Eigen::Index c = 2; c < shifted.cols(); c += 3) shifted.col(c).array() += 0.001f;
  SynthesisScorer moved(p);
  moved.add(recorded, shifted);
  const auto m = moved.score();
  EXPECT_EQ(m.frames, 60u) << "compared over the frames both have";
  EXPECT_NEAR(m.lip_rms_mm, 1.0, 1e-3);
  EXPECT_NEAR(m.all_rms_mm, 1.0, 1e-3);
  EXPECT_NEAR(m.lips.height.correlation, 1.0, 1e-6);

  // A mouth that opens half as far: the height curve still correlates, but its error grows and
  // only the two moving points contribute distance.
  SynthesisScorer half(p);
  half.add(recorded, talking(p, 60, 0.002));
  half.add(recorded, recorded);
  const auto h = half.score();
  EXPECT_EQ(h.utterances, 2u);
  EXPECT_GT(h.lips.height.mean_error_percent, 1.0);
  EXPECT_GT(h.lips.height.correlation, 0.8) << "same shape, half the size in one of two utterances";
  EXPECT_GT(h.lip_rms_mm, h.all_rms_mm) << "the error sits on the lips";
  EXPECT_THROW(half.add(recorded, Eigen::MatrixXf(60, 3)), std::invalid_argument);
}

// The jaw is scored apart from the lips: lips that move as recorded over a chin that does not
// move score r 0 on the jaw (a constant curve) and 1 on lip height; a chin moving against the
// recording's scores r -1; one that moves half as far keeps r 1, its error half the chin's travel.
TEST(SynthesisScorer, ScoresTheJawAtTheChin) {
  const auto f = feature_points();
  const auto p = evaluation_points(f.labels, f.vertices);
  const Eigen::MatrixXf recorded = talking(p, 60, 0.004, 1.0);

  SynthesisScorer still(p);
  still.add(recorded, talking(p, 60, 0.004, 0.0));
  const auto s = still.score();
  EXPECT_NEAR(s.lips.height.correlation, 1.0, 1e-9);
  EXPECT_EQ(s.jaw.correlation, 0.0);
  EXPECT_GT(s.jaw.mean_abs_difference, 0.003) << "the recorded chin travels 4 mm on average";

  SynthesisScorer against(p);
  against.add(recorded, talking(p, 60, 0.004, -1.0));
  EXPECT_NEAR(against.score().jaw.correlation, -1.0, 1e-6);

  SynthesisScorer half(p);
  half.add(recorded, talking(p, 60, 0.004, 0.5));
  const auto h = half.score();
  EXPECT_NEAR(h.jaw.correlation, 1.0, 1e-6);
  EXPECT_NEAR(h.jaw.mean_abs_difference, 0.5 * s.jaw.mean_abs_difference, 1e-6);

  auto without_chin = f;
  const auto chin = std::find(without_chin.labels.begin(), without_chin.labels.end(), "2.1") - without_chin.labels.begin();
  without_chin.labels.erase(without_chin.labels.begin() + chin);
  without_chin.vertices.erase(without_chin.vertices.begin() + chin);
  const auto q = evaluation_points(without_chin.labels, without_chin.vertices);
  SynthesisScorer no_chin(q);
  no_chin.add(talking(q, 60, 0.004), talking(q, 60, 0.004));
  EXPECT_EQ(no_chin.score().jaw.frames, 0u) << "no FP 2.1: the jaw is not scored";
}

}  // namespace
}  // namespace fapcast
