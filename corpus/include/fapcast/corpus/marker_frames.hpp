#pragma once
// Motion-capture marker trajectories, the one layout of the capture readers and writers (C3D,
// TRC, marker CSV), capture clean-up, the reference talker and the evaluation: M labelled
// markers over F frames, positions 3M x F (rows 3m..3m+2 are marker m's x, y, z; column k is
// frame k) in the length unit the type names, NaN where a sample is missing (occluded or
// dropped). Capture files carry millimetres (MarkerFrames<Millimetres>); the face and what is
// computed on it (ICT-FaceKit) carry centimetres (MarkerFrames<Centimetres>).
#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

struct Millimetres {
  static constexpr std::string_view symbol = "mm";
};
struct Centimetres {
  static constexpr std::string_view symbol = "cm";
};

template <class Unit>
struct MarkerFrames {
  std::vector<std::string> labels;  // M labels ("8.3", "H.temple_l", "LCHEEK"); may repeat
  // Frames per second; frame k is at k / frame_rate_hz seconds. A double, because C3D stores a
  // float32 and TRC a decimal: 60 reads back as exactly 60, 59.94 as the nearest double.
  double frame_rate_hz = 60;
  std::int64_t first_frame = 1;  // a file's number for frame 0 (C3D and TRC count from 1)
  Eigen::MatrixXd positions;     // 3M x F in Unit; NaN = missing

  // `markers` x `frames`, every sample missing, labels "".
  static MarkerFrames missing(Eigen::Index markers, Eigen::Index frames) {
    MarkerFrames out;
    out.labels.assign(static_cast<std::size_t>(markers), "");
    out.positions = Eigen::MatrixXd::Constant(3 * markers, frames, std::nan(""));
    return out;
  }

  // `markers` x `frames`, every sample present at the origin, labels "".
  static MarkerFrames zeros(Eigen::Index markers, Eigen::Index frames) {
    MarkerFrames out;
    out.labels.assign(static_cast<std::size_t>(markers), "");
    out.positions = Eigen::MatrixXd::Zero(3 * markers, frames);
    return out;
  }

  Eigen::Index marker_count() const { return positions.rows() / 3; }
  Eigen::Index frame_count() const { return positions.cols(); }
  // Marker m at frame k (NaN when missing).
  Eigen::Vector3d at(Eigen::Index m, Eigen::Index k) const { return positions.template block<3, 1>(3 * m, k); }
  bool present(Eigen::Index m, Eigen::Index k) const { return !std::isnan(positions(3 * m, k)); }
  void set(Eigen::Index m, Eigen::Index k, const Eigen::Vector3d& p) { positions.template block<3, 1>(3 * m, k) = p; }
  // Marks marker m missing at frame k.
  void drop(Eigen::Index m, Eigen::Index k) { positions.template block<3, 1>(3 * m, k).setConstant(std::nan("")); }
  // The index of the first marker called `label`, or nullopt.
  std::optional<Eigen::Index> find(std::string_view label) const {
    for (std::size_t m = 0; m < labels.size(); ++m)
      if (labels[m] == label) return static_cast<Eigen::Index>(m);
    return std::nullopt;
  }
  // Marker m's runs of missing frames, [first, end), in frame order: what gap filling fills.
  struct MissingRun {
    Eigen::Index first, end;
  };
  std::vector<MissingRun> missing_runs(Eigen::Index m) const {
    std::vector<MissingRun> runs;
    for (Eigen::Index k = 0; k < frame_count();) {
      if (present(m, k)) {
        ++k;
        continue;
      }
      Eigen::Index end = k;
      while (end < frame_count() && !present(m, end)) ++end;
      runs.push_back({k, end});
      k = end;
    }
    return runs;
  }
  // Whether labels and positions agree in shape (3 x labels rows).
  bool consistent() const { return positions.rows() == 3 * static_cast<Eigen::Index>(labels.size()); }
  // Equal labels, rate, numbering and positions, a missing sample equal to a missing one.
  bool operator==(const MarkerFrames& o) const {
    if (labels != o.labels || frame_rate_hz != o.frame_rate_hz || first_frame != o.first_frame ||
        positions.rows() != o.positions.rows() || positions.cols() != o.positions.cols())
      return false;
    for (Eigen::Index k = 0; k < positions.cols(); ++k)
      for (Eigen::Index r = 0; r < positions.rows(); ++r) {
        const double a = positions(r, k), b = o.positions(r, k);
        if (a != b && !(std::isnan(a) && std::isnan(b))) return false;
      }
    return true;
  }
};

// Centimetres of the capture's millimetres: each present coordinate / 10.
MarkerFrames<Centimetres> to_centimetres(const MarkerFrames<Millimetres>& markers);
// Millimetres of centimetres: each present coordinate times 10.
MarkerFrames<Millimetres> to_millimetres(const MarkerFrames<Centimetres>& markers);

// Millimetres per one `unit` ("mm" 1, "cm" 10, "m" 1000, "in" 25.4), or nullopt if unknown.
std::optional<double> millimetres_per_unit(std::string_view unit);

template <class Unit>
std::ostream& operator<<(std::ostream& out, const MarkerFrames<Unit>& markers) {
  out << "MarkerFrames " << markers.frame_count() << " frames x " << markers.marker_count() << " markers ("
      << Unit::symbol << ") at " << markers.frame_rate_hz << " Hz:";
  for (const std::string& label : markers.labels) out << " " << label;
  return out;
}

}  // namespace fapcast
