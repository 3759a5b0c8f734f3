#include "fapcast/math/zero_phase_lowpass.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace fapcast {
namespace {

// The filter keeps what moves slowly, takes out what moves fast, and delays nothing: a 2 Hz
// sine plus 60 Hz "jitter" at 500 Hz comes back as the 2 Hz sine in phase, and a ramp (the ends
// reflected oddly) as itself.
TEST(ZeroPhaseLowpass, KeepsSlowMotionInPhaseAndRemovesJitter) {
  std::vector<double> x, slow;
  for (int i = 0; i < 1000; ++i) {
    const double t = i / 500.0;
    slow.push_back(std::sin(2 * std::numbers::pi * 2 * t));
    x.push_back(slow.back() + 0.5 * std::sin(2 * std::numbers::pi * 60 * t));
  }
  const std::vector<double> y = zero_phase_lowpass(x, 500, 15);
  ASSERT_EQ(y.size(), x.size());
  double worst = 0;
  for (int i = 50; i < 950; ++i) worst = std::max(worst, std::abs(y[static_cast<std::size_t>(i)] - slow[static_cast<std::size_t>(i)]));
  EXPECT_LT(worst, 0.01);  // 60 Hz at 15 Hz cut-off: |H|^2 = 1 / (1 + 4^4) ~ 0.004 of 0.5
  std::vector<double> ramp;
  for (int i = 0; i < 50; ++i) ramp.push_back(3 + 0.1 * i);
  const std::vector<double> r = zero_phase_lowpass(ramp, 500, 15);
  for (std::size_t i = 0; i < ramp.size(); ++i) EXPECT_NEAR(r[i], ramp[i], 2e-3) << i;  // 0.03 % of the rise
  // -6 dB at the cut-off (-3 dB per pass).
  std::vector<double> at_cutoff;
  for (int i = 0; i < 5000; ++i) at_cutoff.push_back(std::sin(2 * std::numbers::pi * 15 * i / 500.0));
  const std::vector<double> h = zero_phase_lowpass(at_cutoff, 500, 15);
  double peak = 0;
  for (int i = 1000; i < 4000; ++i) peak = std::max(peak, std::abs(h[static_cast<std::size_t>(i)]));
  EXPECT_NEAR(peak, 0.5, 0.01);
  EXPECT_THROW(zero_phase_lowpass(x, 500, 250), std::invalid_argument);
  EXPECT_THROW(zero_phase_lowpass(x, 0, 15), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
