#include "fapcast/capture/marker_resample.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fapcast {

MarkerFrames<Millimetres> resample_markers(const MarkerFrames<Millimetres>& markers, std::int32_t rate_hz) {
  const double input_hz = markers.frame_rate_hz;
  if (rate_hz < 1 || rate_hz > 100000) throw std::invalid_argument("resample_markers: rate " + std::to_string(rate_hz) + " Hz out of range");
  if (!std::isfinite(input_hz) || !(input_hz > 0)) throw std::invalid_argument("resample_markers: input rate not positive");
  if (!markers.consistent()) throw std::invalid_argument("resample_markers: inconsistent markers");
  const Eigen::Index in_frames = markers.frame_count();
  const Eigen::Index m = markers.marker_count();
  // The source position of output frame k: whole frame i plus a fraction in [0, 1).
  const bool whole_rate = input_hz == std::floor(input_hz) && input_hz <= 1e9;
  const auto in_rate = static_cast<std::int64_t>(input_hz);
  auto source_of = [&](Eigen::Index k, Eigen::Index& i, double& fraction) {
    if (whole_rate) {
      const std::int64_t numerator = static_cast<std::int64_t>(k) * in_rate;
      i = static_cast<Eigen::Index>(numerator / rate_hz);
      fraction = static_cast<double>(numerator % rate_hz) / rate_hz;
    } else {
      const double u = static_cast<double>(k) * input_hz / rate_hz;
      i = static_cast<Eigen::Index>(std::floor(u + 1e-9));  // within rounding of a frame: that frame
      fraction = std::max(0.0, u - static_cast<double>(i));
      if (fraction < 1e-9) fraction = 0;
    }
  };
  Eigen::Index out_frames = 0;
  if (in_frames > 0) {
    if (whole_rate) {
      out_frames = static_cast<Eigen::Index>((static_cast<std::int64_t>(in_frames - 1) * rate_hz) / in_rate) + 1;
    } else {
      // A last frame within rounding of the grid still counts (59.94 x 1001 / 1000 ...).
      out_frames = static_cast<Eigen::Index>(std::floor(static_cast<double>(in_frames - 1) * rate_hz / input_hz + 1e-9)) + 1;
    }
  }
  MarkerFrames<Millimetres> out = MarkerFrames<Millimetres>::missing(m, out_frames);
  out.labels = markers.labels;
  out.frame_rate_hz = rate_hz;
  out.first_frame = 1;
  for (Eigen::Index k = 0; k < out_frames; ++k) {
    Eigen::Index i = 0;
    double t = 0;
    source_of(k, i, t);
    if (i >= in_frames - 1) {  // the last input frame (doubles may land a hair past it)
      i = in_frames - 1;
      t = 0;
    }
    for (Eigen::Index j = 0; j < m; ++j) {
      if (t == 0) {
        if (markers.present(j, i)) out.set(j, k, markers.at(j, i));
      } else if (markers.present(j, i) && markers.present(j, i + 1)) {
        out.set(j, k, (1 - t) * markers.at(j, i) + t * markers.at(j, i + 1));
      }  // else missing, as `out` starts
    }
  }
  return out;
}

}  // namespace fapcast
