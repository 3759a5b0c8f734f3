#include "marker_rows.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"

#include <cmath>

namespace fapcast::detail {

MarkerRows::MarkerRows(std::size_t markers, double mm_per_unit, const std::string& source,
                       std::string_view format)
    : markers_(markers), mm_per_unit_(mm_per_unit), source_(source), format_(format) {}

void MarkerRows::add(std::span<const std::string_view> cells, std::uint64_t line) {
  for (std::size_t m = 0; m < markers_; ++m) {
    std::string_view xyz[3];
    int empty = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t c = 3 * m + k;
      xyz[k] = c < cells.size() ? trim(cells[c]) : std::string_view{};
      empty += xyz[k].empty();
    }
    if (empty == 3) {
      values_.insert(values_.end(), 3, std::nan(""));
      continue;
    }
    if (empty != 0) {
      throw InputError({source_, line, std::nullopt}, format_ + "-partial-sample",
                       "marker " + std::to_string(m + 1) + " has some coordinates empty and some not");
    }
    for (const std::string_view cell : xyz) {
      double v = 0;
      if (!parse_finite(cell, v)) {
        throw InputError({source_, line, std::nullopt}, format_ + "-bad-number",
                         "\"" + excerpt(cell) + "\" is not a finite number");
      }
      values_.push_back(v * mm_per_unit_);
    }
  }
  ++frames_;
}

void MarkerRows::check_frame_number(std::int64_t frame, std::uint64_t line) {
  if (frames_ == 0) {
    first_frame_ = frame;
    return;
  }
  // frame - first_frame_ rather than first_frame_ + frames_: numbers are non-negative, so the
  // difference cannot overflow where the sum could (a first frame near 2^63).
  if (frame < first_frame_ || static_cast<std::uint64_t>(frame - first_frame_) != frames_) {
    throw InputError({source_, line, std::nullopt}, format_ + "-frame-number",
                     "frame " + std::to_string(frame) + " is out of sequence (frame " +
                         std::to_string(static_cast<std::uint64_t>(first_frame_) + frames_) + " comes next)");
  }
}

MarkerFrames<Millimetres> MarkerRows::finish(std::vector<std::string> labels, double frame_rate_hz) const {
  MarkerFrames<Millimetres> out;
  out.labels = std::move(labels);
  out.frame_rate_hz = frame_rate_hz;
  out.first_frame = first_frame_;
  // values_ holds frame after frame of x y z per marker: the 3M x F layout, column by column.
  out.positions = Eigen::Map<const Eigen::MatrixXd>(values_.data(), static_cast<Eigen::Index>(3 * markers_),
                                                    static_cast<Eigen::Index>(frames_));
  return out;
}

std::string marker_row_lines(const MarkerFrames<Millimetres>& markers, char separator) {
  std::string out;
  for (Eigen::Index f = 0; f < markers.frame_count(); ++f) {
    out += std::to_string(markers.first_frame + f) + separator +
           shortest_decimal(static_cast<double>(f) / markers.frame_rate_hz);
    for (Eigen::Index m = 0; m < markers.marker_count(); ++m)
      for (int k = 0; k < 3; ++k) {
        out += separator;
        if (markers.present(m, f)) out += shortest_decimal(markers.positions(3 * m + k, f));
      }
    out += "\n";
  }
  return out;
}

}  // namespace fapcast::detail
