#include "fapcast/math/sample_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace fapcast {

double percentile(std::span<const double> x, double p) {
  if (!(p >= 0 && p <= 100)) throw std::invalid_argument("percentile: needs 0 <= p <= 100");
  std::vector<double> s;  // NaN (a missing sample) skipped, as pearson_correlation does: sort needs an order
  s.reserve(x.size());
  for (const double v : x)
    if (!std::isnan(v)) s.push_back(v);
  if (s.empty()) throw std::invalid_argument("percentile: no sample that is a number");
  std::sort(s.begin(), s.end());
  const double pos = p / 100 * static_cast<double>(s.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, s.size() - 1);
  return s[lo] + (pos - static_cast<double>(lo)) * (s[hi] - s[lo]);
}

double pearson_correlation(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size())
    throw std::invalid_argument("correlation: curves of " + std::to_string(a.size()) + " and " +
                                std::to_string(b.size()) + " samples");
  double n = 0, mean_a = 0, mean_b = 0;
  for (std::size_t t = 0; t < a.size(); ++t) {
    if (std::isnan(a[t]) || std::isnan(b[t])) continue;
    mean_a += a[t];
    mean_b += b[t];
    ++n;
  }
  if (n < 2) return 0.0;
  mean_a /= n;
  mean_b /= n;
  double saa = 0, sbb = 0, sab = 0;
  for (std::size_t t = 0; t < a.size(); ++t) {
    if (std::isnan(a[t]) || std::isnan(b[t])) continue;
    const double da = a[t] - mean_a, db = b[t] - mean_b;
    saa += da * da;
    sbb += db * db;
    sab += da * db;
  }
  return (saa > 0 && sbb > 0) ? sab / std::sqrt(saa * sbb) : 0.0;
}

}  // namespace fapcast
