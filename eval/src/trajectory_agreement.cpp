#include "fapcast/eval/trajectory_agreement.hpp"

#include "fapcast/math/sample_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace fapcast {
namespace {

double spread(std::span<const double> x) { return percentile(x, 95) - percentile(x, 5); }

// r(reference(t), compared(t + delay)) over the samples where t + delay lies on the curve.
double delayed_r(std::span<const double> ref, std::span<const double> cmp, double rate_hz, double delay_s) {
  const double shift = delay_s * rate_hz;  // in samples
  std::vector<double> a, b;
  a.reserve(ref.size());
  b.reserve(ref.size());
  const double last = static_cast<double>(cmp.size() - 1);
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const double pos = static_cast<double>(i) + shift;
    if (pos < 0 || pos > last) continue;
    const auto lo = static_cast<std::size_t>(std::floor(pos));
    const std::size_t hi = std::min(lo + 1, cmp.size() - 1);
    a.push_back(ref[i]);
    b.push_back(cmp[lo] + (pos - static_cast<double>(lo)) * (cmp[hi] - cmp[lo]));
  }
  return a.size() >= 2 ? pearson_correlation(a, b) : 0.0;
}

}  // namespace

TrajectoryAgreement trajectory_agreement(std::span<const double> reference, std::span<const double> compared,
                                         double rate_hz, double max_lag_s, double step_s) {
  if (reference.size() != compared.size() || reference.size() < 3)
    throw std::invalid_argument("trajectory_agreement: needs two curves of the same length >= 3");
  if (!(rate_hz > 0) || !(max_lag_s >= 0) || !(step_s > 0))
    throw std::invalid_argument("trajectory_agreement: needs rate > 0, max lag >= 0, step > 0");
  TrajectoryAgreement out;
  out.reference_range = spread(reference);
  out.compared_range = spread(compared);
  out.range_ratio = out.reference_range > 0 ? out.compared_range / out.reference_range : 0.0;
  out.r_zero_lag = pearson_correlation(reference, compared);
  out.r_best_lag = out.r_zero_lag;
  const auto steps = static_cast<long>(std::floor(max_lag_s / step_s + 1e-9));
  // Outwards from zero, so that ties go to the smallest delay.
  for (long k = 1; k <= steps; ++k) {
    for (const double d : {static_cast<double>(k) * step_s, -static_cast<double>(k) * step_s}) {
      const double r = delayed_r(reference, compared, rate_hz, d);
      if (r > out.r_best_lag + 1e-12) {
        out.r_best_lag = r;
        out.best_lag_s = d;
      }
    }
  }
  return out;
}

std::vector<double> correlation_loss_by_span(std::span<const double> reference, std::span<const double> compared,
                                             std::span<const SampleSpan> spans) {
  if (reference.size() != compared.size())
    throw std::invalid_argument("correlation_loss_by_span: curves of " + std::to_string(reference.size()) + " and " +
                                std::to_string(compared.size()) + " samples");
  const auto both = [&](std::size_t t) { return !std::isnan(reference[t]) && !std::isnan(compared[t]); };
  double n = 0, mean_r = 0, mean_c = 0;
  for (std::size_t t = 0; t < reference.size(); ++t)
    if (both(t)) {
      n += 1;
      mean_r += reference[t];
      mean_c += compared[t];
    }
  if (n > 0) {
    mean_r /= n;
    mean_c /= n;
  }
  double var_r = 0, var_c = 0;
  for (std::size_t t = 0; t < reference.size(); ++t)
    if (both(t)) {
      var_r += (reference[t] - mean_r) * (reference[t] - mean_r);
      var_c += (compared[t] - mean_c) * (compared[t] - mean_c);
    }
  const double sd_r = std::sqrt(var_r / std::max(n, 1.0)), sd_c = std::sqrt(var_c / std::max(n, 1.0));
  const bool flat = !(sd_r > 0 && sd_c > 0);  // pearson_correlation's r = 0
  std::vector<double> out;
  out.reserve(spans.size());
  for (const SampleSpan& s : spans) {
    if (s.begin > s.end || s.end > reference.size())
      throw std::invalid_argument("correlation_loss_by_span: span [" + std::to_string(s.begin) + ", " +
                                  std::to_string(s.end) + ") of curves of " + std::to_string(reference.size()) +
                                  " samples");
    double loss = 0;
    for (std::size_t t = s.begin; t < s.end; ++t) {
      if (!both(t)) continue;
      if (flat) {
        loss += 1 / n;
        continue;
      }
      const double d = (compared[t] - mean_c) / sd_c - (reference[t] - mean_r) / sd_r;
      loss += d * d / (2 * n);
    }
    out.push_back(loss);
  }
  return out;
}

}  // namespace fapcast
