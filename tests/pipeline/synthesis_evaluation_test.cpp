// The held-out evaluation end to end on a small face whose "mesh" is the marker set itself: a
// system that reproduces the recording scores (nearly) perfectly, one that does nothing does not.
#include "fapcast/eval/synthesis_evaluation.hpp"

#include "fapcast/face/marker_map.hpp"
#include "fapcast/talker/reference_talker.hpp"

#include <gtest/gtest.h>

#include <Eigen/SVD>

#include <algorithm>
#include <numeric>

namespace fapcast {
namespace {

// Source vectors: every marker, metres; the face's "vertex" of a marker is its row.
Eigen::MatrixXd markers_m(const MarkerFrames<Centimetres>& take) { return 0.01 * take.positions; }

TEST(EvaluateSynthesis, AnOracleBeatsAFrozenFace) {
  const FaceModel actor = reference_actor(ict_face_model(), 1);
  const auto held = record_held_out(actor, 7, 2);
  ASSERT_EQ(held.size(), 2u);
  EXPECT_NE(held[0].text, held[1].text);
  for (const auto& u : held) {
    ASSERT_FALSE(u.targets.empty());
    EXPECT_NEAR(static_cast<double>(u.targets.back().end_frame), static_cast<double>(u.recorded.frame_count()), 2.0)
        << "targets span the recording";
    EXPECT_EQ(u.targets.front().first_frame, 0) << "the grid starts at sample 0";
  }

  // An (almost) identity retargeting map fitted on 21 frames of the first utterance.
  const Eigen::MatrixXd x = markers_m(held[0].recorded);
  const int m = 21;
  Eigen::MatrixXd centres(m, x.rows());
  for (int i = 0; i < m; ++i) centres.row(i) = x.col(i * (x.cols() - 1) / (m - 1)).transpose();
  const double r2 = (x.colwise() - x.rowwise().mean()).colwise().squaredNorm().mean();
  const RbfMap map = fit_rbf_by_gcv(centres, centres, r2);
  const Retargeting retarget(map, std::nullopt);

  std::vector<std::string> labels;
  std::vector<std::int32_t> rows;
  for (std::size_t i = 0; i < marker_sites().size(); ++i)
    if (marker_sites()[i].role != MarkerRole::rigid)
      labels.emplace_back(marker_sites()[i].label), rows.push_back(static_cast<std::int32_t>(i));
  const std::array<std::int32_t, 2> temples{static_cast<std::int32_t>(marker_row("H.temple_l")),
                                            static_cast<std::int32_t>(marker_row("H.temple_r"))};
  std::vector<std::int32_t> all(marker_sites().size());
  std::iota(all.begin(), all.end(), 0);

  // PCA of the mapped recordings (the "voice" frames): mean and 12 components.
  std::vector<Eigen::MatrixXf> truth;
  Eigen::Index frames = 0;
  for (const auto& u : held) truth.push_back(vertex_tracks(retarget, markers_m(u.recorded), all)), frames += truth.back().rows();
  Eigen::MatrixXf stacked(frames, truth[0].cols());
  frames = 0;
  for (const auto& t : truth) stacked.middleRows(frames, t.rows()) = t, frames += t.rows();
  const RowMajorMatrixXf mean = stacked.colwise().mean();
  const Eigen::JacobiSVD<Eigen::MatrixXf> svd(stacked.rowwise() - mean.row(0), Eigen::ComputeThinV);
  const RowMajorMatrixXf components = svd.matrixV().leftCols(12).transpose();

  using Map = Eigen::Map<const RowMajorMatrixXf>;
  const EvaluationFace face{Map(mean.data(), mean.rows(), mean.cols()),
                            Map(components.data(), components.rows(), components.cols()), &retarget,
                            markers_m, evaluation_points(labels, rows, temples)};

  const std::vector<NamedSystem> systems{
      {"oracle", [&](const HeldOutUtterance& u) {
         const Eigen::MatrixXf t = vertex_tracks(retarget, markers_m(u.recorded), all);
         const Eigen::MatrixXf c = (t.rowwise() - mean.row(0)) * components.transpose();
         const Eigen::Index lead = u.targets.front().first_frame;
         return SystemOutput{c.bottomRows(c.rows() - lead), u.targets.size()};
       }},
      {"frozen", [&](const HeldOutUtterance& u) {
         return SystemOutput{Eigen::MatrixXf::Zero(u.targets.back().end_frame - u.targets.front().first_frame, 12), 0};
       }}};
  const auto report = evaluate_synthesis(face, systems, held);
  ASSERT_EQ(report.systems.size(), 2u);
  ASSERT_EQ(report.utterances.size(), 2u);
  const auto& oracle = report.systems[0];
  const auto& frozen = report.systems[1];
  EXPECT_EQ(oracle.units_per_phone, 1.0);
  EXPECT_EQ(frozen.units_per_phone, 0.0);
  EXPECT_LT(oracle.score.all_rms_mm, 0.2) << "12 components of the recording's own PCA";
  EXPECT_GT(frozen.score.lip_rms_mm, 5 * oracle.score.lip_rms_mm);
  EXPECT_GT(oracle.score.lips.height.correlation, 0.99);
  EXPECT_LT(oracle.score.lips.height.mean_error_percent, 1.0);
  EXPECT_GT(frozen.score.lips.height.mean_error_percent, 5 * oracle.score.lips.height.mean_error_percent);
  EXPECT_EQ(report.utterances[0].synthesised.size(), 2u);
  EXPECT_EQ(report.utterances[0].recorded.size(), static_cast<std::size_t>(held[0].recorded.frame_count()));
  // Mouth opening on the target face in mm: plausible speech, neither zero nor metres.
  const auto& h = report.utterances[0].recorded.height;
  EXPECT_GT(*std::max_element(h.begin(), h.end()), 5.0);
  EXPECT_LT(*std::max_element(h.begin(), h.end()), 60.0);

  const std::vector<NamedSystem> wrong{{"wrong-k", [](const HeldOutUtterance&) { return SystemOutput{Eigen::MatrixXf::Zero(3, 5), 0}; }}};
  EXPECT_THROW(evaluate_synthesis(face, wrong, held), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
