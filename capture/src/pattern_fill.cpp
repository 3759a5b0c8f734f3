#include "fapcast/capture/pattern_fill.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fapcast {
namespace {

// RMS about its mean of a(f) - b(f) (b = nullptr: of a(f) alone) over the frames of [first, end)
// where both are present; infinity with fewer than two such frames.
double offset_spread(const MarkerFrames<Centimetres>& frames, Eigen::Index a, const Eigen::Index* b,
                     Eigen::Index first, Eigen::Index end) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double squared = 0;
  int n = 0;
  for (Eigen::Index f = first; f < end; ++f) {
    if (!frames.present(a, f) || (b != nullptr && !frames.present(*b, f))) continue;
    const Eigen::Vector3d d = b == nullptr ? frames.at(a, f) : Eigen::Vector3d(frames.at(a, f) - frames.at(*b, f));
    sum += d;
    squared += d.squaredNorm();
    ++n;
  }
  if (n < 2) return std::numeric_limits<double>::infinity();
  return std::sqrt(std::max(0.0, squared / n - (sum / n).squaredNorm()));
}

}  // namespace

PatternFillResult pattern_fill(const MarkerFrames<Centimetres>& frames, std::span<const std::size_t> donor_rows,
                               const PatternFillOptions& options) {
  PatternFillResult out{frames, {}};
  const Eigen::Index count = frames.frame_count();
  for (const std::size_t row : donor_rows) {
    const auto m = static_cast<Eigen::Index>(row);
    if (m >= frames.marker_count()) continue;
    for (const auto [gap_first, gap_end] : frames.missing_runs(m)) {
      const bool before = gap_first > 0, after = gap_end < count;  // the present edges
      if (!before && !after) continue;
      const Eigen::Index from = before ? gap_first - 1 : gap_first, to = after ? gap_end + 1 : gap_end;
      const Eigen::Index lo = std::max<Eigen::Index>(0, gap_first - options.window_frames);
      const Eigen::Index hi = std::min(count, gap_end + options.window_frames);
      double best = offset_spread(frames, m, nullptr, lo, hi);  // a straight line's "donor"
      Eigen::Index donor = -1;
      for (const std::size_t other : donor_rows) {
        const auto d = static_cast<Eigen::Index>(other);
        if (d == m || d >= frames.marker_count()) continue;
        bool covers = true;
        for (Eigen::Index f = from; f < to && covers; ++f) covers = frames.present(d, f);
        if (!covers) continue;
        const double spread = offset_spread(frames, m, &d, lo, hi);
        if (spread < best) best = spread, donor = d;
      }
      if (donor < 0) continue;
      const Eigen::Vector3d first_offset = before ? Eigen::Vector3d(frames.at(m, from) - frames.at(donor, from))
                                                  : Eigen::Vector3d(frames.at(m, gap_end) - frames.at(donor, gap_end));
      const Eigen::Vector3d last_offset = after ? Eigen::Vector3d(frames.at(m, gap_end) - frames.at(donor, gap_end))
                                                : first_offset;
      for (Eigen::Index f = gap_first; f < gap_end; ++f) {
        const double t = before && after ? static_cast<double>(f - from) / static_cast<double>(gap_end - from) : 0.0;
        out.frames.set(m, f, frames.at(donor, f) + (1 - t) * first_offset + t * last_offset);
      }
      out.filled.push_back({m, gap_first, gap_end - gap_first, donor});
    }
  }
  return out;
}

}  // namespace fapcast
