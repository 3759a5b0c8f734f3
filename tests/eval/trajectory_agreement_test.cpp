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

TEST(TrajectoryAgreement, TheLossOfRSplitsOverSpansAndAddsUpToOneMinusR) {
  std::vector<double> real, ours;
  for (int i = 0; i < 300; ++i) {
    const double t = i / 100.0;
    real.push_back(movement(t));
    // The same movement, scaled and offset, except in the second of three seconds.
    ours.push_back(3 + 2 * (t >= 1 && t < 2 ? -movement(t) : movement(t)));
  }
  const double r = trajectory_agreement(real, ours, 100).r_zero_lag;
  ASSERT_LT(r, 0.9);
  const std::vector<SampleSpan> thirds{{0, 100}, {100, 200}, {200, 300}};
  const std::vector<double> loss = correlation_loss_by_span(real, ours, thirds);
  ASSERT_EQ(loss.size(), 3u);
  EXPECT_NEAR(loss[0] + loss[1] + loss[2], 1 - r, 1e-12);
  // The second second, where the curves move against each other, holds most of the loss.
  EXPECT_GT(loss[1], 4 * (loss[0] + loss[2]));
  for (const double l : loss) EXPECT_GE(l, 0);
  // Spans need not cover the curves; an empty span loses nothing.
  const std::vector<SampleSpan> some{{100, 150}, {150, 200}, {7, 7}};
  const std::vector<double> part = correlation_loss_by_span(real, ours, some);
  EXPECT_NEAR(part[0] + part[1], loss[1], 1e-12);
  EXPECT_EQ(part[2], 0);

  // A scaled, offset copy loses nothing anywhere.
  std::vector<double> copy;
  for (const double v : real) copy.push_back(5 - 0.5 * -v);
  for (const double l : correlation_loss_by_span(real, copy, thirds)) EXPECT_NEAR(l, 0, 1e-12);
}

TEST(TrajectoryAgreement, TheLossOfAFlatOrGappedCurveStillAddsUpToOneMinusR) {
  std::vector<double> real, flat(300, 2.0);
  for (int i = 0; i < 300; ++i) real.push_back(movement(i / 100.0));
  const std::vector<SampleSpan> halves{{0, 150}, {150, 300}};
  const std::vector<double> f = correlation_loss_by_span(real, flat, halves);
  EXPECT_NEAR(f[0], 0.5, 1e-12);  // r = 0: each sample loses 1/n
  EXPECT_NEAR(f[1], 0.5, 1e-12);

  // Samples that are not numbers (a coil's gap) are left out, as pearson_correlation leaves them.
  std::vector<double> ours = real;
  for (int i = 0; i < 300; ++i) ours[i] += 0.3 * std::sin(i / 7.0);
  for (int i = 40; i < 60; ++i) ours[i] = std::nan("");
  const double r = trajectory_agreement(real, ours, 100).r_zero_lag;
  const std::vector<double> g = correlation_loss_by_span(real, ours, halves);
  EXPECT_NEAR(g[0] + g[1], 1 - r, 1e-12);
  EXPECT_FALSE(std::isnan(g[0]));

  EXPECT_THROW(correlation_loss_by_span(real, std::vector<double>(299, 0.0), halves), std::invalid_argument);
  EXPECT_THROW(correlation_loss_by_span(real, ours, std::vector<SampleSpan>{{0, 301}}), std::invalid_argument);
  EXPECT_THROW(correlation_loss_by_span(real, ours, std::vector<SampleSpan>{{20, 10}}), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
