#include "fapcast/math/zero_phase_lowpass.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fapcast {
namespace {

// Biquad coefficients of a 2nd-order Butterworth low-pass by the bilinear transform with
// pre-warping (the audio-EQ-cookbook form with Q = 1/sqrt 2).
struct Biquad {
  double b0, b1, b2, a1, a2;
};

Biquad butterworth(double rate_hz, double cutoff_hz) {
  const double w = 2 * std::numbers::pi * cutoff_hz / rate_hz;
  const double alpha = std::sin(w) / std::numbers::sqrt2;  // sin(w) / (2 Q), Q = 1/sqrt(2)
  const double c = std::cos(w);
  const double a0 = 1 + alpha;
  return {(1 - c) / 2 / a0, (1 - c) / a0, (1 - c) / 2 / a0, -2 * c / a0, (1 - alpha) / a0};
}

// One pass, the state started at rest on the first sample (direct form II transposed).
void run(const Biquad& f, std::vector<double>& x) {
  // Steady state for a constant input x0: z1 = x0 (1 - b0), z2 = x0 (b2 - a2)... solved below.
  const double x0 = x.front();
  double z1 = x0 * (1 - f.b0);
  double z2 = x0 * (f.b2 - f.a2);
  for (double& v : x) {
    const double y = f.b0 * v + z1;
    z1 = f.b1 * v - f.a1 * y + z2;
    z2 = f.b2 * v - f.a2 * y;
    v = y;
  }
}

}  // namespace

std::vector<double> zero_phase_lowpass(std::span<const double> x, double rate_hz, double cutoff_hz) {
  if (!(rate_hz > 0) || !(cutoff_hz > 0) || !(cutoff_hz < rate_hz / 2))
    throw std::invalid_argument("zero_phase_lowpass: needs rate > 0 and 0 < cut-off < rate / 2");
  const std::size_t n = x.size();
  if (n < 3) return {x.begin(), x.end()};
  const Biquad f = butterworth(rate_hz, cutoff_hz);
  // Odd reflection of about 3 time constants of the filter (at least 3 samples, at most n - 1).
  const std::size_t pad = std::min(n - 1, std::max<std::size_t>(3, static_cast<std::size_t>(3 * rate_hz / cutoff_hz)));
  std::vector<double> y;
  y.reserve(n + 2 * pad);
  for (std::size_t i = pad; i >= 1; --i) y.push_back(2 * x[0] - x[i]);
  y.insert(y.end(), x.begin(), x.end());
  for (std::size_t i = 1; i <= pad; ++i) y.push_back(2 * x[n - 1] - x[n - 1 - i]);
  run(f, y);
  std::reverse(y.begin(), y.end());
  run(f, y);
  std::reverse(y.begin(), y.end());
  return {y.begin() + static_cast<std::ptrdiff_t>(pad), y.begin() + static_cast<std::ptrdiff_t>(pad + n)};
}

}  // namespace fapcast
