#pragma once
// A take of 3-D marker trajectories: M labelled markers over F frames; a missing sample is NaN.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace fapcast {

struct MarkerFrames {
  std::vector<std::string> labels;  // M labels ("2.2", "H.temple_l" ...)
  std::int32_t frame_rate_hz = 60;  // frame k is at k / frame_rate_hz seconds
  Eigen::MatrixXd positions_cm;     // 3M x F: rows 3m..3m+2 are marker m's x, y, z; NaN = missing

  Eigen::Index marker_count() const { return positions_cm.rows() / 3; }
  Eigen::Index frame_count() const { return positions_cm.cols(); }
  // Marker m at frame k (NaN when missing).
  Eigen::Vector3d at(Eigen::Index m, Eigen::Index k) const { return positions_cm.block<3, 1>(3 * m, k); }
  bool present(Eigen::Index m, Eigen::Index k) const { return !std::isnan(positions_cm(3 * m, k)); }
  // Marks marker m missing at frame k.
  void drop(Eigen::Index m, Eigen::Index k) {
    positions_cm.block<3, 1>(3 * m, k).setConstant(std::nan(""));
  }
};

}  // namespace fapcast
