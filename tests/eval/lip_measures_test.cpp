#include "fapcast/eval/lip_measures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace fapcast {
namespace {

// A take of the six lip-measure markers (plus one unrelated marker first, so rows are looked up
// by label rather than assumed), `frames` long, with the mouth opening by 0.1 cm per frame.
MarkerFrames<Centimetres> opening_mouth(Eigen::Index frames) {
  MarkerFrames<Centimetres> take;
  take.labels = {"2.1", "8.1", "8.2", "8.3", "8.4", "H.temple_l", "H.temple_r"};
  take.positions.setZero(3 * 7, frames);
  for (Eigen::Index k = 0; k < frames; ++k) {
    take.positions.block<3, 1>(3, k) = Eigen::Vector3d(0, 0.5, 10);         // 8.1
    take.positions.block<3, 1>(6, k) = Eigen::Vector3d(0, -0.5 - 0.1 * k, 10);  // 8.2
    take.positions.block<3, 1>(9, k) = Eigen::Vector3d(2.5, 0, 9);          // 8.3
    take.positions.block<3, 1>(12, k) = Eigen::Vector3d(-2.5, 0, 9);        // 8.4
    take.positions.block<3, 1>(15, k) = Eigen::Vector3d(7, 3.5, 0);         // H.temple_l
    take.positions.block<3, 1>(18, k) = Eigen::Vector3d(-7, 3.5, 0);        // H.temple_r
  }
  return take;
}

TEST(LipMeasures, HeightWidthAndProtrusionAreTheDistancesOfSection41) {
  const LipMeasures m = measure_lips({Eigen::Vector3d(0, 1, 10), Eigen::Vector3d(0, -2, 10),
                                      Eigen::Vector3d(3, 0, 9), Eigen::Vector3d(-3, 0, 9),
                                      Eigen::Vector3d(0, 5, 6)});
  EXPECT_DOUBLE_EQ(m.height, 3.0);
  EXPECT_DOUBLE_EQ(m.width, 6.0);
  EXPECT_DOUBLE_EQ(m.protrusion, std::sqrt(32.0));  // (0, 1, 10) - (0, 5, 6) = (0, -4, 4)
}

TEST(LipMeasures, CurvesOfATakeFollowTheMarkersAndSkipMissingFrames) {
  MarkerFrames<Centimetres> take = opening_mouth(4);
  take.drop(5, 2);  // H.temple_l missing at frame 2
  const LipCurves curves = lip_curves(take);
  ASSERT_EQ(curves.size(), 4u);
  EXPECT_NEAR(curves.height[0], 1.0, 1e-12);
  EXPECT_NEAR(curves.height[3], 1.3, 1e-12);
  EXPECT_NEAR(curves.width[1], 5.0, 1e-12);
  // Reference = (0, 3.5, 0): protrusion = |(0, -3, 10)|.
  EXPECT_NEAR(curves.protrusion[0], std::sqrt(109.0), 1e-12);
  EXPECT_TRUE(std::isnan(curves.height[2]));
  EXPECT_TRUE(std::isnan(curves.protrusion[2]));
}

TEST(LipMeasures, ATakeWithoutTheTempleMarkersIsRefusedByName) {
  MarkerFrames<Centimetres> take = opening_mouth(2);
  take.labels[6] = "H.forehead";
  try {
    (void)lip_curves(take);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("H.temple_r"), std::string::npos) << e.what();
  }
}

TEST(LipMeasures, MeshFramesGiveTheSameCurvesAsMarkersAtTheSameVertices) {
  const MarkerFrames<Centimetres> take = opening_mouth(5);
  // A "mesh" of 7 vertices whose vertex v is marker v; frames are rows.
  Eigen::MatrixXf frames = take.positions.transpose().cast<float>();
  const std::array<std::int32_t, 6> vertices = {1, 2, 3, 4, 5, 6};
  const LipCurves from_mesh = lip_curves(frames, vertices);
  const LipCurves from_markers = lip_curves(take);
  ASSERT_EQ(from_mesh.size(), from_markers.size());
  for (std::size_t k = 0; k < from_mesh.size(); ++k) {
    EXPECT_NEAR(from_mesh.height[k], from_markers.height[k], 1e-5);
    EXPECT_NEAR(from_mesh.protrusion[k], from_markers.protrusion[k], 1e-5);
  }
  const std::array<std::int32_t, 6> outside = {1, 2, 3, 4, 5, 7};
  EXPECT_THROW((void)lip_curves(frames, outside), std::invalid_argument);
}

TEST(LipMeasures, ComparisonNormalisesEachCurveByItsOwnMaximum) {
  // The same motion on a face twice the size agrees exactly.
  const std::vector<double> small = {1.0, 0.5, 0.75, 1.0};
  const std::vector<double> large = {2.0, 1.0, 1.5, 2.0};
  const CurveAgreement same = compare_curves(small, large);
  EXPECT_NEAR(same.mean_error_percent, 0.0, 1e-12);
  EXPECT_NEAR(same.correlation, 1.0, 1e-12);
  EXPECT_EQ(same.frames, 4u);
  EXPECT_NEAR(same.mean_abs_difference, 0.8125, 1e-12) << "in the curves' own unit: the faces differ in size";
  // Against a constant curve: |1-1| + |0.5-1| + |0.75-1| + |1-1| = 0.75 over 4 frames.
  const std::vector<double> flat = {3.0, 3.0, 3.0, 3.0};
  const CurveAgreement off = compare_curves(small, flat);
  EXPECT_NEAR(off.mean_error_percent, 18.75, 1e-12);
  EXPECT_EQ(off.correlation, 0.0);
  // Mirror image motion correlates negatively; NaN frames are skipped.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> mirrored = {0.5, 1.0, nan, 0.5};
  const CurveAgreement mirror = compare_curves(small, mirrored);
  EXPECT_EQ(mirror.frames, 3u);
  EXPECT_NEAR(mirror.mean_abs_difference, (0.5 + 0.5 + 0.5) / 3, 1e-12) << "NaN frames skipped";
  EXPECT_NEAR(mirror.correlation, -1.0, 1e-12);
  EXPECT_THROW((void)compare_curves(small, std::vector<double>{1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
