#include "fapcast/corpus/marker_set.hpp"

namespace fapcast {

MarkerSet MarkerSet::zeros(Eigen::Index frames, Eigen::Index markers) {
  MarkerSet set;
  set.labels.assign(static_cast<std::size_t>(markers), "");
  set.positions_mm = Positions::Zero(frames, 3 * markers);
  set.missing = Mask::Constant(frames, markers, false);
  return set;
}

std::optional<Eigen::Index> MarkerSet::find(std::string_view label) const {
  for (std::size_t m = 0; m < labels.size(); ++m) {
    if (labels[m] == label) return static_cast<Eigen::Index>(m);
  }
  return std::nullopt;
}

bool MarkerSet::consistent() const {
  return positions_mm.cols() == 3 * marker_count() && missing.cols() == marker_count() &&
         missing.rows() == positions_mm.rows();
}

bool MarkerSet::operator==(const MarkerSet& o) const {
  return labels == o.labels && frame_rate_hz == o.frame_rate_hz && first_frame == o.first_frame &&
         positions_mm.rows() == o.positions_mm.rows() && positions_mm.cols() == o.positions_mm.cols() &&
         positions_mm == o.positions_mm && missing.rows() == o.missing.rows() &&
         missing.cols() == o.missing.cols() && (missing == o.missing).all();
}

std::optional<double> millimetres_per_unit(std::string_view unit) {
  if (unit == "mm") return 1.0;
  if (unit == "cm") return 10.0;
  if (unit == "m") return 1000.0;
  if (unit == "in") return 25.4;
  return std::nullopt;
}

std::ostream& operator<<(std::ostream& out, const MarkerSet& markers) {
  out << "MarkerSet " << markers.frame_count() << " frames x " << markers.marker_count()
      << " markers at " << markers.frame_rate_hz << " Hz:";
  for (const std::string& label : markers.labels) out << " " << label;
  return out;
}

}  // namespace fapcast
