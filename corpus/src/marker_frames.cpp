#include "fapcast/corpus/marker_frames.hpp"

namespace fapcast {

MarkerFrames<Centimetres> to_centimetres(const MarkerFrames<Millimetres>& markers) {
  MarkerFrames<Centimetres> out;
  out.labels = markers.labels;
  out.frame_rate_hz = markers.frame_rate_hz;
  out.first_frame = markers.first_frame;
  out.positions = markers.positions / 10.0;  // NaN stays NaN
  return out;
}

MarkerFrames<Millimetres> to_millimetres(const MarkerFrames<Centimetres>& markers) {
  MarkerFrames<Millimetres> out;
  out.labels = markers.labels;
  out.frame_rate_hz = markers.frame_rate_hz;
  out.first_frame = markers.first_frame;
  out.positions = 10.0 * markers.positions;
  return out;
}

std::optional<double> millimetres_per_unit(std::string_view unit) {
  if (unit == "mm") return 1.0;
  if (unit == "cm") return 10.0;
  if (unit == "m") return 1000.0;
  if (unit == "in") return 25.4;
  return std::nullopt;
}

}  // namespace fapcast
