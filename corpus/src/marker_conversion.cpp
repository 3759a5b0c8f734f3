#include "fapcast/corpus/marker_conversion.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fapcast {

MarkerSet to_marker_set(const MarkerFrames& frames) {
  const Eigen::Index f = frames.frame_count(), m = frames.marker_count();
  MarkerSet set = MarkerSet::zeros(f, m);
  set.labels = frames.labels;
  set.frame_rate_hz = frames.frame_rate_hz;
  for (Eigen::Index k = 0; k < f; ++k)
    for (Eigen::Index i = 0; i < m; ++i) {
      if (frames.present(i, k)) set.set_position(k, i, 10.0 * frames.at(i, k));
      else set.missing(k, i) = true;
    }
  return set;
}

MarkerFrames to_marker_frames(const MarkerSet& set) {
  const double rate = set.frame_rate_hz;
  if (!(rate >= 1.0) || std::abs(rate - std::round(rate)) > 1e-3 || rate > 100000.0)
    throw std::invalid_argument("markers: frame rate " + std::to_string(rate) +
                                " Hz is not a whole number of frames per second");
  MarkerFrames frames;
  frames.labels = set.labels;
  frames.frame_rate_hz = static_cast<std::int32_t>(std::lround(rate));
  frames.positions_cm.resize(3 * set.marker_count(), set.frame_count());
  for (Eigen::Index k = 0; k < set.frame_count(); ++k)
    for (Eigen::Index i = 0; i < set.marker_count(); ++i) {
      if (set.missing(k, i)) frames.drop(i, k);
      else frames.positions_cm.block<3, 1>(3 * i, k) = set.position(k, i) / 10.0;
    }
  return frames;
}

}  // namespace fapcast
