#include "fapcast/eval/trajectory_agreement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace fapcast {
namespace {

// A smooth, non-periodic curve at 100 Hz over 3 s.
double movement(double t) {
  return std::sin(2 * std::numbers::pi * 1.3 * t) + 0.5 * std::sin(2 * std::numbers::pi * 3.1 * t + 1);
}

TEST(TrajectoryAgreement, ACopyDelayedAndScaledGivesItsLagRatioAndR) {
  std::vector<double> real, ours;
  for (int i = 0; i < 300; ++i) {
    const double t = i / 100.0;
    real.push_back(movement(t));
    ours.push_back(4 + 1.5 * movement(t - 0.040));  // 40 ms behind, 1.5 x the range, offset
  }
  const TrajectoryAgreement a = trajectory_agreement(real, ours, 100);
  EXPECT_NEAR(a.range_ratio, 1.5, 0.01);
  EXPECT_NEAR(a.compared_range / a.reference_range, a.range_ratio, 1e-12);
  EXPECT_NEAR(a.best_lag_s, 0.040, 1e-9);
  EXPECT_NEAR(a.r_best_lag, 1, 1e-3);
  EXPECT_LT(a.r_zero_lag, a.r_best_lag - 0.01);

  // Ahead instead of behind: the lag is negative.
  std::vector<double> early;
  for (int i = 0; i < 300; ++i) early.push_back(0.5 * movement(i / 100.0 + 0.025));
  const TrajectoryAgreement b = trajectory_agreement(real, early, 100);
  EXPECT_NEAR(b.best_lag_s, -0.025, 1e-9);
  EXPECT_NEAR(b.range_ratio, 0.5, 0.01);
  EXPECT_NEAR(b.r_best_lag, 1, 1e-3);
}

TEST(TrajectoryAgreement, AnUnrelatedOrFlatCurveScoresNothing) {
  std::vector<double> real, flat(300, 2.0), inverted;
  for (int i = 0; i < 300; ++i) {
    real.push_back(movement(i / 100.0));
    inverted.push_back(-real.back());
  }
  const TrajectoryAgreement f = trajectory_agreement(real, flat, 100);
  EXPECT_EQ(f.range_ratio, 0);
  EXPECT_EQ(f.r_zero_lag, 0);
  EXPECT_EQ(f.best_lag_s, 0);  // no delay does better than none
  EXPECT_NEAR(trajectory_agreement(real, inverted, 100).r_zero_lag, -1, 1e-12);
  EXPECT_EQ(trajectory_agreement(flat, real, 100).range_ratio, 0);  // a flat reference
  EXPECT_THROW(trajectory_agreement(real, std::vector<double>(299, 0.0), 100), std::invalid_argument);
  EXPECT_THROW(trajectory_agreement(real, real, 0), std::invalid_argument);
  EXPECT_THROW(trajectory_agreement(real, real, 100, -0.1), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
