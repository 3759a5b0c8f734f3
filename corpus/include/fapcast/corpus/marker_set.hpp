#pragma once
// Motion-capture marker trajectories: F frames x M markers x 3 coordinates, in millimetres, with
// a mask of missing samples (occluded or dropped markers), as C3D, TRC and marker CSV carry them.
#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

struct MarkerSet {
  using Positions = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  using Mask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  std::vector<std::string> labels;  // M marker names ("8.3", "LCHEEK", "HEAD_L"); may repeat
  // Frames per second. A double, because C3D stores a float32 and TRC a decimal: 60 reads back
  // as exactly 60; a rate such as 59.94 is the nearest double (float for C3D).
  double frame_rate_hz = 60;
  std::int64_t first_frame = 1;  // the file's number for frame 0 (C3D and TRC count from 1)
  // F x 3M, row f = x0 y0 z0 x1 y1 z1 ... of frame f, millimetres in the capture's frame.
  Positions positions_mm;
  // F x M, true where a sample is missing; its position is then 0 0 0.
  Mask missing;

  // An empty set of `frames` x `markers`: all positions 0, nothing missing, labels "".
  static MarkerSet zeros(Eigen::Index frames, Eigen::Index markers);

  Eigen::Index frame_count() const { return positions_mm.rows(); }
  Eigen::Index marker_count() const { return static_cast<Eigen::Index>(labels.size()); }
  // Position of `marker` in `frame`, mm (0 0 0 where missing).
  Eigen::Vector3d position(Eigen::Index frame, Eigen::Index marker) const {
    return positions_mm.block<1, 3>(frame, 3 * marker).transpose();
  }
  void set_position(Eigen::Index frame, Eigen::Index marker, const Eigen::Vector3d& p_mm) {
    positions_mm.block<1, 3>(frame, 3 * marker) = p_mm.transpose();
  }
  // The index of the first marker called `label`, or nullopt.
  std::optional<Eigen::Index> find(std::string_view label) const;
  // Whether labels, positions and mask agree in shape (F x 3M and F x M).
  bool consistent() const;
  bool operator==(const MarkerSet& other) const;
};

// Millimetres per one `unit` ("mm" 1, "cm" 10, "m" 1000, "in" 25.4), or nullopt if unknown.
std::optional<double> millimetres_per_unit(std::string_view unit);

std::ostream& operator<<(std::ostream& out, const MarkerSet& markers);

}  // namespace fapcast
