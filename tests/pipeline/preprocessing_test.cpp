// Preprocessing on data whose ground truth is known: rigid fit, head-pose removal, gap filling.
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

#include "fapcast/talker/capture_imperfections.hpp"
#include "fapcast/capture/gap_fill.hpp"
#include "fapcast/capture/head_pose.hpp"
#include "fapcast/capture/pattern_fill.hpp"
#include "fapcast/capture/preprocessing.hpp"
#include "fapcast/talker/talker_markers.hpp"
#include "support/test_timeline.hpp"

namespace fapcast {
namespace {

Eigen::Matrix3d random_rotation(PortableRandom& random) {
  Eigen::Quaterniond q(random.normal(), random.normal(), random.normal(), random.normal());
  return q.normalized().toRotationMatrix();
}

// "a pup strewn", the clean SYNTHETIC marker take of the generic face.
const MarkerFrames<Centimetres>& clean_take() {
  static const MarkerFrames<Centimetres> take = talker_markers(
      ict_face_model(), test::timeline({{"sil", 200}, {"AH0", 70}, {"P", 70}, {"AH1", 100}, {"P", 80},
                                        {"S", 90}, {"T", 50}, {"R", 60}, {"UW1", 180}, {"N", 80},
                                        {"sil", 200}}));
  return take;
}

TEST(RigidFit, RecoversRandomMotionsExactlyAtAnyScale) {
  const auto seed = test::test_seed(test::kTimelineSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  PortableRandom random(seed);
  for (const double scale : {1e-6, 1.0, 1e6}) {
    for (int trial = 0; trial < 50; ++trial) {
      const int n = 3 + static_cast<int>(random.below(10));
      Eigen::Matrix3Xd from(3, n);
      for (int i = 0; i < n; ++i) from.col(i) = scale * Eigen::Vector3d(random.normal(), random.normal(), random.normal());
      const Eigen::Matrix3d r = random_rotation(random);
      const Eigen::Vector3d t = scale * Eigen::Vector3d(random.normal(), random.normal(), random.normal());
      const Eigen::Matrix3Xd to = (r * from).colwise() + t;
      const RigidTransform fit = fit_rigid_transform(from, to);
      EXPECT_LT((fit.rotation - r).norm(), 1e-9) << "scale " << scale;
      EXPECT_LT((fit.translation - t).norm(), 1e-9 * scale);
      EXPECT_NEAR(fit.rotation.determinant(), 1.0, 1e-12);
    }
  }
}

// The best orthogonal map onto a mirror image is a reflection; the guard returns a rotation.
TEST(RigidFit, ReflectionGuardReturnsAProperRotation) {
  Eigen::Matrix3Xd from(3, 4);
  from << 0, 1, 0, 0,  //
      0, 0, 1, 0,      //
      0, 0, 0, 1;
  Eigen::Matrix3Xd mirrored = from;
  mirrored.row(0) *= -1.0;
  const RigidTransform fit = fit_rigid_transform(from, mirrored);
  EXPECT_NEAR(fit.rotation.determinant(), 1.0, 1e-12);
  EXPECT_LT((fit.rotation * fit.rotation.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

TEST(RigidFit, RefusesTooFewOrCollinearPoints) {
  Eigen::Matrix3Xd two = Eigen::Matrix3Xd::Random(3, 2);
  EXPECT_THROW((void)fit_rigid_transform(two, two), std::invalid_argument);
  Eigen::Matrix3Xd line(3, 4);
  line << 0, 1, 2, 3, 0, 2, 4, 6, 0, 3, 6, 9;
  EXPECT_THROW((void)fit_rigid_transform(line, line), std::invalid_argument);
  EXPECT_THROW((void)fit_rigid_transform(line, two), std::invalid_argument);
}

// Known take + known head motion + 0.2 mm noise: pose removal recovers the face motion to within
// the noise level. Bound: RMS 3-D error below 2 x the noise's own RMS 3-D size (sqrt(3) x 0.2 mm
// = 0.35 mm): the pose error of a fit on 5 rigid markers, seen at the mouth about 15 cm from
// their centroid, adds about as much again (measured: 1.45-1.55 x).
TEST(HeadPoseRemoval, RecoversFaceMotionToWithinTheNoise) {
  const auto seed = test::test_seed(test::kTimelineSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  PortableRandom random(seed);
  const MarkerFrames<Centimetres>& clean = clean_take();
  const auto rigid = rigid_marker_rows();
  const Eigen::Matrix3Xd reference = rigid_reference(clean, rigid, 0);
  constexpr double kSigmaMm = 0.2;
  const double noise_rms_cm = std::sqrt(3.0) * kSigmaMm / 10.0;
  for (int take = 0; take < 5; ++take) {
    MarkerFrames<Centimetres> captured = clean;
    const HeadMotion motion(random, {3.0, 3.0});
    apply_head_motion(captured, motion);
    const double moved_rms = std::sqrt((captured.positions - clean.positions).colwise().squaredNorm().mean() /
                                       static_cast<double>(clean.marker_count()));
    add_marker_noise(captured, random, kSigmaMm);
    const PoseRemovalResult result = remove_head_pose(captured, rigid, reference);
    EXPECT_TRUE(result.frames_without_pose.empty());
    const Eigen::MatrixXd error = result.frames.positions - clean.positions;
    double squared = 0;
    double worst = 0;
    for (Eigen::Index m = 0; m < clean.marker_count(); ++m)
      for (Eigen::Index k = 0; k < clean.frame_count(); ++k) {
        const double e = error.block<3, 1>(3 * m, k).norm();
        squared += e * e;
        worst = std::max(worst, e);
      }
    const double rms = std::sqrt(squared / static_cast<double>(clean.marker_count() * clean.frame_count()));
    EXPECT_LT(rms, 2.0 * noise_rms_cm) << "take " << take;
    EXPECT_LT(worst, 6.0 * noise_rms_cm) << "take " << take;
    EXPECT_GT(moved_rms, 5.0 * noise_rms_cm) << "head motion too small to test anything";
    EXPECT_LT(result.rms_rigid_residual_cm, 1.5 * noise_rms_cm);
  }
}

TEST(HeadPoseRemoval, FramesWithFewerThanThreeRigidMarkersAreReported) {
  MarkerFrames<Centimetres> captured = clean_take();
  const auto rigid = rigid_marker_rows();
  const Eigen::Matrix3Xd reference = rigid_reference(captured, rigid, 0);
  for (std::size_t r = 0; r < 3; ++r) captured.drop(static_cast<Eigen::Index>(rigid[r]), 10);
  for (std::size_t r = 0; r < 2; ++r) captured.drop(static_cast<Eigen::Index>(rigid[r]), 11);
  const auto result = remove_head_pose(captured, rigid, reference);
  EXPECT_EQ(result.frames_without_pose, std::vector<Eigen::Index>{10});
  EXPECT_FALSE(result.frames.present(0, 10));
  EXPECT_TRUE(result.frames.present(0, 11));  // three rigid markers left: still fitted
  EXPECT_THROW((void)rigid_reference(captured, rigid, 10), std::invalid_argument);
}

// A take with one marker moving on smooth curves (speech-like: 1-4 Hz, cm amplitudes).
MarkerFrames<Centimetres> smooth_take(Eigen::Index frames) {
  MarkerFrames<Centimetres> take{{"a", "b"}, 60, 1, Eigen::MatrixXd(6, frames)};
  for (Eigen::Index k = 0; k < frames; ++k) {
    const double t = static_cast<double>(k) / 60.0;
    take.positions.col(k) << 0.5 * std::sin(2 * M_PI * 1.3 * t), 0.3 * std::cos(2 * M_PI * 2.1 * t) + 0.2 * std::sin(2 * M_PI * 0.7 * t),
        0.1 * t, 1.0 + 0.4 * t, -2.0 + 0.1 * t, 0.25 * std::sin(2 * M_PI * 3.0 * t);
  }
  return take;
}

TEST(GapFill, SplineInterpolatesItsKnotsAndReproducesLines) {
  const Eigen::VectorXd x = (Eigen::VectorXd(5) << 0, 1, 3, 4, 7).finished();
  const Eigen::VectorXd y = (Eigen::VectorXd(5) << 1, -1, 2, 0, 5).finished();
  EXPECT_LT((natural_cubic_spline(x, y, x) - y).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::VectorXd line = 2.0 * x.array() - 3.0;
  const Eigen::VectorXd xs = (Eigen::VectorXd(3) << 0.5, 2.2, 6.9).finished();
  EXPECT_LT((natural_cubic_spline(x, line, xs) - (2.0 * xs.array() - 3.0).matrix()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_THROW((void)natural_cubic_spline(x.head(1), y.head(1), xs), std::invalid_argument);
}

// Error of filled gaps on smooth trajectories, by gap length: at most 0.05 mm for 3 frames,
// 0.5 mm for 6, 3 mm for 12 (the longest filled), always below the straight-line chord.
TEST(GapFill, FillsShortGapsOfSmoothTrajectoriesAccurately) {
  const MarkerFrames<Centimetres> truth = smooth_take(240);
  for (const auto& [length, bound_mm] : {std::pair<Eigen::Index, double>{3, 0.05}, {6, 0.5}, {12, 3.0}}) {
    MarkerFrames<Centimetres> holed = truth;
    for (Eigen::Index start : {20, 90, 170})
      for (Eigen::Index k = start; k < start + length; ++k) holed.drop(0, k);
    const GapFillResult filled = fill_gaps(holed, {12});
    ASSERT_EQ(filled.gaps.size(), 3u);
    EXPECT_EQ(filled.unfilled_count(), 0u);
    const double error_mm = 10.0 * (filled.frames.positions - truth.positions).cwiseAbs().maxCoeff();
    EXPECT_LT(error_mm, bound_mm) << "gap of " << length << " frames";
  }
}

// Speech moves the lips fast (a bilabial release opens them ~8 mm in ~60 ms), so only short gaps
// are filled by default (4 frames). Measured over every position in "a pup strewn": RMS error of
// the lower lip 8.2 is 0.23 mm for 1-frame gaps and 1.1 mm for 4-frame gaps.
TEST(GapFill, FillsTheTalkersLipMarkerGapsUpToTheDefaultLength) {
  const MarkerFrames<Centimetres>& truth = clean_take();
  const auto lip = static_cast<Eigen::Index>(marker_row("8.2"));
  for (const auto& [length, bound_mm] : {std::pair<Eigen::Index, double>{1, 0.3}, {4, 1.3}}) {
    double squared = 0;
    int samples = 0;
    for (Eigen::Index start = 2; start + length + 2 < truth.frame_count(); ++start) {
      MarkerFrames<Centimetres> holed = truth;
      for (Eigen::Index k = start; k < start + length; ++k) holed.drop(lip, k);
      const GapFillResult filled = fill_gaps(holed);
      ASSERT_EQ(filled.unfilled_count(), 0u);
      for (Eigen::Index k = start; k < start + length; ++k, ++samples)
        squared += (filled.frames.at(lip, k) - truth.at(lip, k)).squaredNorm();
    }
    EXPECT_LT(10.0 * std::sqrt(squared / samples), bound_mm) << length << "-frame gaps";
  }
}

TEST(GapFill, ReportsLongEdgeAndHopelessGapsWithoutFillingThem) {
  MarkerFrames<Centimetres> holed = smooth_take(120);
  for (Eigen::Index k = 40; k < 53; ++k) holed.drop(0, k);  // 13 frames: one too many
  for (Eigen::Index k = 0; k < 4; ++k) holed.drop(0, k);    // at the start
  for (Eigen::Index k = 1; k < 120; ++k) holed.drop(1, k);  // one sample left
  const GapFillResult filled = fill_gaps(holed, {12});
  ASSERT_EQ(filled.gaps.size(), 3u);
  EXPECT_EQ(filled.gaps[0].outcome, GapOutcome::at_edge);
  EXPECT_EQ(filled.gaps[0].frame_count, 4);
  EXPECT_EQ(filled.gaps[1].outcome, GapOutcome::too_long);
  EXPECT_EQ(filled.gaps[1].first_frame, 40);
  EXPECT_EQ(filled.gaps[1].frame_count, 13);
  EXPECT_EQ(filled.gaps[2].outcome, GapOutcome::too_few_samples);
  EXPECT_EQ(filled.unfilled_count(), 3u);
  for (Eigen::Index k = 40; k < 53; ++k) EXPECT_FALSE(filled.frames.present(0, k));
  // With a longer limit the same gap is filled.
  EXPECT_EQ(fill_gaps(holed, {13}).gaps[1].outcome, GapOutcome::filled);
}

// The whole capture chain as record-reference runs it: capture_take, then preprocess_take.
TEST(Preprocessing, CaptureChainRoundTrip) {
  const auto seed = test::test_seed(test::kTimelineSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  PortableRandom random(seed);
  const MarkerFrames<Centimetres>& clean = clean_take();
  CaptureSettings settings;
  settings.dropouts = {30.0, 8};
  const CapturedTake take = capture_take(clean, random, settings);
  EXPECT_FALSE(take.dropped.empty());
  const auto result = preprocess_take(take.frames, rigid_marker_rows(), rigid_reference(clean, rigid_marker_rows(), 0));
  EXPECT_TRUE(result.frames_without_pose.empty());
  std::size_t reported = 0;
  for (const auto& gap : result.gaps) reported += gap.outcome == GapOutcome::filled ? 0 : 1;
  EXPECT_GT(result.gaps.size(), reported);  // some filled, and with 8-frame runs some reported
  double squared = 0;
  Eigen::Index samples = 0;
  for (Eigen::Index m = 0; m < clean.marker_count(); ++m)
    for (Eigen::Index k = 0; k < clean.frame_count(); ++k)
      if (result.frames.present(m, k)) {
        squared += (result.frames.at(m, k) - clean.at(m, k)).squaredNorm();
        ++samples;
      }
  EXPECT_GT(samples, clean.marker_count() * clean.frame_count() * 9 / 10);
  EXPECT_LT(std::sqrt(squared / static_cast<double>(samples)) * 10.0, 0.6);  // mm
  // Reproducible: the same seed gives the same take, bit for bit.
  PortableRandom again(seed);
  const CapturedTake repeat = capture_take(clean, again, settings);
  EXPECT_TRUE((take.frames.positions.array() == repeat.frames.positions.array() ||
               (take.frames.positions.array().isNaN() && repeat.frames.positions.array().isNaN()))
                  .all());
}

}  // namespace
}  // namespace fapcast

namespace fapcast {
namespace {

// A long gap in a lip marker, filled from a donor on the same lip (pattern fill) against the
// straight line between its edges that the voice build drew before: RMS error over every gap
// position in "a pup strewn", 6 and 12 frames, for the lips' four mid points.
TEST(PatternFill, BridgesLongLipGapsFarBetterThanAStraightLine) {
  const MarkerFrames<Centimetres>& truth = clean_take();
  std::vector<std::size_t> donors;
  for (std::size_t r = 0; r < marker_sites().size(); ++r)
    if (marker_sites()[r].role != MarkerRole::rigid) donors.push_back(r);
  for (const char* label : {"8.1", "8.2", "2.2", "2.3"}) {
    const auto lip = static_cast<Eigen::Index>(marker_row(label));
    for (const Eigen::Index length : {6, 12}) {
      double pattern = 0, line = 0;
      int samples = 0;
      for (Eigen::Index start = 2; start + length + 2 < truth.frame_count(); start += 2) {
        MarkerFrames<Centimetres> holed = truth;
        for (Eigen::Index k = start; k < start + length; ++k) holed.drop(lip, k);
        const PatternFillResult filled = pattern_fill(holed, donors);
        ASSERT_EQ(filled.filled.size(), 1u) << label << " at " << start;
        EXPECT_EQ(filled.filled[0].frame_count, length);
        const Eigen::Vector3d a = truth.at(lip, start - 1), b = truth.at(lip, start + length);
        for (Eigen::Index k = start; k < start + length; ++k, ++samples) {
          pattern += (filled.frames.at(lip, k) - truth.at(lip, k)).squaredNorm();
          const double t = static_cast<double>(k - start + 1) / static_cast<double>(length + 1);
          line += ((1 - t) * a + t * b - truth.at(lip, k)).squaredNorm();
        }
      }
      const double pattern_mm = 10 * std::sqrt(pattern / samples), line_mm = 10 * std::sqrt(line / samples);
      std::cout << label << ", " << length << "-frame gaps: pattern fill " << pattern_mm << " mm RMS, straight line "
                << line_mm << " mm\n";
      EXPECT_LT(pattern_mm, 0.5 * line_mm) << label << ", " << length << " frames";
    }
  }
}

// No donor present over the gap, or none that moves with the marker more closely than the marker
// moves alone: the gap is left for the caller's straight line.
TEST(PatternFill, LeavesGapsWithoutAFittingDonor) {
  MarkerFrames<Centimetres> two = MarkerFrames<Centimetres>::missing(2, 20);
  for (Eigen::Index f = 0; f < 20; ++f) {
    two.set(0, f, Eigen::Vector3d(0.1 * static_cast<double>(f), 0, 0));  // a steady line
    two.set(1, f, Eigen::Vector3d(0, std::sin(static_cast<double>(f)), 0));  // unrelated motion
  }
  for (Eigen::Index f = 8; f < 14; ++f) two.drop(0, f);
  const std::vector<std::size_t> donors{0, 1};
  EXPECT_TRUE(pattern_fill(two, donors).filled.empty());  // marker 1 moves more than marker 0 alone
  for (Eigen::Index f = 0; f < 20; ++f) two.set(1, f, two.present(0, f) ? Eigen::Vector3d(two.at(0, f) + Eigen::Vector3d(0, 1, 0)) : Eigen::Vector3d(0.1 * static_cast<double>(f), 1, 0));
  two.drop(1, 10);  // the donor itself missing inside the gap
  EXPECT_TRUE(pattern_fill(two, donors).filled.empty());
  two.set(1, 10, Eigen::Vector3d(1.0, 1, 0));
  const PatternFillResult filled = pattern_fill(two, donors);
  ASSERT_EQ(filled.filled.size(), 1u);
  EXPECT_EQ(filled.filled[0].donor, 1);
  for (Eigen::Index f = 8; f < 14; ++f) EXPECT_NEAR(filled.frames.at(0, f).x(), 0.1 * static_cast<double>(f), 1e-12);
}

}  // namespace
}  // namespace fapcast
