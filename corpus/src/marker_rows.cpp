#include "marker_rows.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"

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
      values_.insert(values_.end(), 3, 0.0);
      missing_.push_back(true);
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
    missing_.push_back(false);
  }
  ++frames_;
}

MarkerSet MarkerRows::finish(std::vector<std::string> labels, double frame_rate_hz,
                             std::int64_t first_frame) const {
  MarkerSet set = MarkerSet::zeros(static_cast<Eigen::Index>(frames_), static_cast<Eigen::Index>(markers_));
  set.labels = std::move(labels);
  set.frame_rate_hz = frame_rate_hz;
  set.first_frame = first_frame;
  for (std::size_t f = 0; f < frames_; ++f) {
    for (std::size_t m = 0; m < markers_; ++m) {
      const auto fi = static_cast<Eigen::Index>(f);
      const auto mi = static_cast<Eigen::Index>(m);
      set.missing(fi, mi) = missing_[f * markers_ + m];
      for (std::size_t k = 0; k < 3; ++k) {
        set.positions_mm(fi, 3 * mi + static_cast<Eigen::Index>(k)) = values_[(f * markers_ + m) * 3 + k];
      }
    }
  }
  return set;
}

std::string marker_cells(const MarkerSet& markers, Eigen::Index frame, char separator) {
  std::string out;
  for (Eigen::Index m = 0; m < markers.marker_count(); ++m) {
    for (int k = 0; k < 3; ++k) {
      if (m + k > 0) out += separator;
      if (!markers.missing(frame, m)) out += shortest_decimal(markers.positions_mm(frame, 3 * m + k));
    }
  }
  return out;
}

}  // namespace fapcast::detail
