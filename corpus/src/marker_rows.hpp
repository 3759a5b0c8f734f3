#pragma once
// Private: the row-per-frame layout that TRC and marker CSV share (three cells per marker, empty
// cells for a missing sample), read into and written from MarkerFrames<Centimetres> (mm).
#include "fapcast/corpus/marker_frames.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast::detail {

class MarkerRows {
 public:
  // `format` prefixes rule ids ("trc" -> "trc-partial-sample").
  MarkerRows(std::size_t markers, double mm_per_unit, const std::string& source, std::string_view format);

  // Adds one frame from its coordinate cells (x y z per marker; missing trailing cells count as
  // empty). Throws InputError for a half-empty sample or a cell that is not a number.
  void add(std::span<const std::string_view> cells, std::uint64_t line);
  std::size_t frames() const { return frames_; }

  // Checks the number of the frame about to be added: the first one sets the numbering, each later
  // one must be the next. Throws InputError ("<format>-frame-number") otherwise.
  void check_frame_number(std::int64_t frame, std::uint64_t line);

  // The set of the frames added so far, numbered from the first frame's number.
  MarkerFrames<Millimetres> finish(std::vector<std::string> labels, double frame_rate_hz) const;

 private:
  std::size_t markers_;
  double mm_per_unit_;
  const std::string& source_;
  std::string format_;
  std::size_t frames_ = 0;
  std::int64_t first_frame_ = 1;
  std::vector<double> values_;  // grows one frame at a time: never sized from a header count; NaN = missing
};

// One line per frame: its number (first_frame + k), its time in seconds and its 3M cells,
// joined by `separator`: shortest decimals, empty cells where a sample is missing.
std::string marker_row_lines(const MarkerFrames<Millimetres>& markers, char separator);

}  // namespace fapcast::detail
