#include "fapcast/capture/gap_fill.hpp"

#include <algorithm>
#include <stdexcept>

namespace fapcast {

std::size_t GapFillResult::unfilled_count() const {
  return static_cast<std::size_t>(std::count_if(
      gaps.begin(), gaps.end(), [](const MarkerGap& g) { return g.outcome != GapOutcome::filled; }));
}

Eigen::VectorXd natural_cubic_spline(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                     const Eigen::VectorXd& xs) {
  const Eigen::Index n = x.size();
  if (n < 2 || y.size() != n) throw std::invalid_argument("natural_cubic_spline: needs n >= 2 knots");
  for (Eigen::Index i = 1; i < n; ++i)
    if (!(x(i) > x(i - 1))) throw std::invalid_argument("natural_cubic_spline: x not increasing");
  // Second derivatives m with m(0) = m(n-1) = 0: tridiagonal system solved by Thomas' algorithm.
  Eigen::VectorXd m = Eigen::VectorXd::Zero(n);
  if (n > 2) {
    const Eigen::Index k = n - 2;
    Eigen::VectorXd diag(k), upper(k), rhs(k);
    for (Eigen::Index i = 1; i <= k; ++i) {
      const double h0 = x(i) - x(i - 1), h1 = x(i + 1) - x(i);
      diag(i - 1) = 2 * (h0 + h1);
      upper(i - 1) = h1;  // also the sub-diagonal of the next row (symmetric)
      rhs(i - 1) = 6 * ((y(i + 1) - y(i)) / h1 - (y(i) - y(i - 1)) / h0);
    }
    for (Eigen::Index i = 1; i < k; ++i) {
      const double w = upper(i - 1) / diag(i - 1);
      diag(i) -= w * upper(i - 1);
      rhs(i) -= w * rhs(i - 1);
    }
    m(k) = rhs(k - 1) / diag(k - 1);
    for (Eigen::Index i = k - 1; i >= 1; --i) m(i) = (rhs(i - 1) - upper(i - 1) * m(i + 1)) / diag(i - 1);
  }
  Eigen::VectorXd out(xs.size());
  for (Eigen::Index j = 0; j < xs.size(); ++j) {
    const double t = xs(j);
    auto i = static_cast<Eigen::Index>(std::upper_bound(x.data(), x.data() + n, t) - x.data()) - 1;
    i = std::clamp<Eigen::Index>(i, 0, n - 2);
    const double h = x(i + 1) - x(i);
    const double a = (x(i + 1) - t) / h, b = (t - x(i)) / h;
    out(j) = a * y(i) + b * y(i + 1) + ((a * a * a - a) * m(i) + (b * b * b - b) * m(i + 1)) * h * h / 6;
  }
  return out;
}

GapFillResult fill_gaps(const MarkerFrames<Centimetres>& frames, const GapFillOptions& options) {
  GapFillResult result{frames, {}};
  const Eigen::Index count = frames.frame_count();
  for (Eigen::Index m = 0; m < frames.marker_count(); ++m) {
    std::vector<Eigen::Index> present;
    for (Eigen::Index k = 0; k < count; ++k)
      if (frames.present(m, k)) present.push_back(k);
    if (static_cast<Eigen::Index>(present.size()) == count) continue;
    std::vector<Eigen::Index> to_fill;
    for (const auto [k, end] : frames.missing_runs(m)) {
      MarkerGap gap{m, k, end - k, GapOutcome::filled};
      if (present.size() < 2) gap.outcome = GapOutcome::too_few_samples;
      else if (k == 0 || end == count) gap.outcome = GapOutcome::at_edge;
      else if (end - k > options.max_gap_frames) gap.outcome = GapOutcome::too_long;
      if (gap.outcome == GapOutcome::filled)
        for (Eigen::Index f = k; f < end; ++f) to_fill.push_back(f);
      result.gaps.push_back(gap);
    }
    if (to_fill.empty()) continue;
    Eigen::VectorXd x(static_cast<Eigen::Index>(present.size()));
    for (std::size_t i = 0; i < present.size(); ++i) x(static_cast<Eigen::Index>(i)) = static_cast<double>(present[i]);
    Eigen::VectorXd xs(static_cast<Eigen::Index>(to_fill.size()));
    for (std::size_t i = 0; i < to_fill.size(); ++i) xs(static_cast<Eigen::Index>(i)) = static_cast<double>(to_fill[i]);
    for (Eigen::Index c = 0; c < 3; ++c) {
      Eigen::VectorXd y(x.size());
      for (Eigen::Index i = 0; i < x.size(); ++i) y(i) = frames.positions(3 * m + c, present[static_cast<std::size_t>(i)]);
      const Eigen::VectorXd filled = natural_cubic_spline(x, y, xs);
      for (Eigen::Index i = 0; i < xs.size(); ++i)
        result.frames.positions(3 * m + c, to_fill[static_cast<std::size_t>(i)]) = filled(i);
    }
  }
  return result;
}

}  // namespace fapcast
