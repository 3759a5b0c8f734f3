#include "fapcast/math/running_moments.hpp"

#include <gtest/gtest.h>

#include "support/talking_markers.hpp"

namespace fapcast {
namespace {

TEST(RunningMoments, SpreadAndCovarianceAgreeWithTwoPassFormulas) {
  const std::uint64_t seed = test::test_seed(test::kTalkingMarkerSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  const Eigen::MatrixXd frames = test::smooth_shape_map(test::articulation(5000, seed), 12, seed + 1);
  RunningSpread spread(12);
  RunningCovariance cov(12);
  for (Eigen::Index t = 0; t < frames.cols(); ++t) {
    spread.add(frames.col(t));
    cov.add(frames.col(t));
  }
  const Eigen::VectorXd mean = frames.rowwise().mean();
  const Eigen::MatrixXd centred = frames.colwise() - mean;
  const Eigen::MatrixXd two_pass = centred * centred.transpose() / 5000.0;
  EXPECT_EQ(spread.count(), 5000);
  EXPECT_LT((spread.mean() - mean).norm(), 1e-12);
  EXPECT_NEAR(spread.mean_squared_distance(), centred.colwise().squaredNorm().mean(), 1e-12);
  EXPECT_LT((cov.covariance() - two_pass).norm(), 1e-12 * two_pass.norm() + 1e-18);
  // r^2 is the trace of the covariance.
  EXPECT_NEAR(spread.mean_squared_distance(), cov.covariance().trace(), 1e-12);
}

TEST(RunningMoments, RejectsWrongLengthAndKeepsLargeOffsetsAccurate) {
  RunningSpread spread(2);
  EXPECT_THROW(spread.add(Eigen::VectorXd::Zero(3)), std::invalid_argument);
  EXPECT_THROW(RunningSpread(0), std::invalid_argument);
  // Values 1e6 + {0, 1}: a naive E[x^2] - E[x]^2 in double would lose the answer.
  for (int i = 0; i < 1000; ++i) spread.add(Eigen::Vector2d(1e6 + (i % 2), 1e6));
  EXPECT_NEAR(spread.mean_squared_distance(), 0.25, 1e-9);
  EXPECT_EQ(RunningCovariance(3).covariance(), Eigen::MatrixXd::Zero(3, 3));
}

}  // namespace
}  // namespace fapcast
