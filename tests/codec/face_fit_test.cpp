// fit_generic_face: a scaled, moved copy of the generic face without its tongue tip gets the
// tongue tip and both pivots back exactly.
#include "fapcast/codec/face_geometry.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

TEST(FitGenericFace, RecoversPivotsAndMissingPointsOfAScaledCopy) {
  const FaceGeometry generic = generic_adult_face();
  const Eigen::Vector3d shift{0.02, 1.6, -0.03};
  auto moved = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d { return 0.0093 * p + shift; };  // cm -> ~m
  FeaturePointPositions measured;
  for (const auto& [fp, at] : generic.feature_points)
    if (fp != FeaturePoint{6, 1}) measured[fp] = moved(at);
  const FaceGeometry face = fit_generic_face(measured);
  EXPECT_LT((face.at({6, 1}) - moved(generic.at({6, 1}))).norm(), 1e-12);
  EXPECT_LT((face.jaw_pivot - moved(generic.jaw_pivot)).norm(), 1e-12);
  EXPECT_LT((face.head_pivot - moved(generic.head_pivot)).norm(), 1e-12);
  EXPECT_EQ(face.at({2, 1}), measured.at({2, 1}));
  EXPECT_NEAR(face.jaw_length(), 0.0093 * generic.jaw_length(), 1e-12);

  EXPECT_THROW(fit_generic_face({{{2, 1}, Eigen::Vector3d::Zero()}}), std::invalid_argument);
  FeaturePointPositions mirrored;
  for (const auto& [fp, at] : generic.feature_points) mirrored[fp] = -at;
  EXPECT_THROW(fit_generic_face(mirrored), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
