#include "fapcast/corpus/trc.hpp"

#include "fapcast/core/input_error.hpp"
#include "marker_rows.hpp"
#include "fapcast/core/text_input.hpp"

#include <stdexcept>

namespace fapcast {
namespace {

constexpr std::size_t kHeaderLines = 5;  // PathFileType, keys, values, names, X1 Y1 Z1

}  // namespace

MarkerFrames<Millimetres> read_trc(std::string_view bytes, const std::string& source) {
  const std::string text = decode_text(bytes, source, "trc");
  const std::vector<TextLine> lines = split_lines(text);
  auto fail = [&](std::uint64_t line, const char* rule, const std::string& detail) {
    fail_at_line(source, line, rule, detail);
  };
  if (lines.size() < kHeaderLines) {
    fail(lines.size() + 1, "trc-truncated", "a TRC file has 5 header lines");
  }
  if (!lines[0].text.starts_with("PathFileType")) {
    fail(1, "trc-header", "the first line does not start with PathFileType");
  }
  const auto keys = split_fields(lines[1].text, '\t');
  const auto values = split_fields(lines[2].text, '\t');
  auto value_of = [&](std::string_view key) -> std::string_view {
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (trim(keys[i]) == key) {
        if (i >= values.size()) fail(3, "trc-header", std::string(key) + " has no value");
        return trim(values[i]);
      }
    }
    fail_at_line(source, 2, "trc-header", "the header has no " + std::string(key));
  };
  double rate_hz = 0;
  if (!parse_finite(value_of("DataRate"), rate_hz) || rate_hz <= 0) {
    fail(3, "trc-bad-rate", "DataRate \"" + excerpt(value_of("DataRate")) + "\" is not a positive number");
  }
  std::int64_t frame_count = 0;
  std::int64_t marker_count = 0;
  if (!parse_count(value_of("NumFrames"), frame_count) ||
      !parse_count(value_of("NumMarkers"), marker_count)) {
    fail(3, "trc-header", "NumFrames and NumMarkers must be counts");
  }
  const std::string units(value_of("Units"));
  const std::optional<double> mm = millimetres_per_unit(units);
  if (!mm) fail(3, "trc-units", "Units \"" + excerpt(units) + "\" is not mm, cm, m or in");

  // Names: every non-empty cell after Frame# and Time (each marker spans three columns).
  const auto name_cells = split_fields(lines[3].text, '\t');
  std::vector<std::string> labels;
  for (std::size_t i = 2; i < name_cells.size(); ++i) {
    const std::string_view name = trim(name_cells[i]);
    if (name.empty()) continue;
    if ((i - 2) % 3 != 0) fail(4, "trc-marker-names", "marker name \"" + excerpt(name) + "\" is not in column 3 + 3k");
    labels.emplace_back(name);
  }
  if (static_cast<std::int64_t>(labels.size()) != marker_count) {
    fail(4, "trc-marker-count", "NumMarkers is " + std::to_string(marker_count) + " but " +
                                    std::to_string(labels.size()) + " markers are named");
  }

  detail::MarkerRows rows(labels.size(), *mm, source, "trc");
  std::uint64_t implied_cells = 0;
  for (std::size_t i = kHeaderLines; i < lines.size(); ++i) {
    if (trim(lines[i].text).empty()) continue;  // Vicon leaves a blank line
    const auto cells = split_fields(lines[i].text, '\t');
    std::int64_t frame = 0;
    if (!parse_count(trim(cells[0]), frame)) {
      fail(lines[i].number, "trc-frame-number", "\"" + excerpt(cells[0]) + "\" is not a frame number");
    }
    rows.check_frame_number(frame, lines[i].number);
    const std::size_t coordinates = cells.size() < 2 ? 0 : cells.size() - 2;
    for (std::size_t c = 3 * labels.size(); c < coordinates; ++c) {
      if (!trim(cells[2 + c]).empty()) {
        fail(lines[i].number, "trc-fields", "more coordinates than 3 x NumMarkers");
      }
    }
    // Trimmed trailing cells are missing samples that cost no bytes; bound them by the file
    // size so that a short file cannot make the reader allocate rows x NumMarkers values.
    implied_cells += 3 * labels.size() - std::min(coordinates, 3 * labels.size());
    if (implied_cells > bytes.size()) {
      fail(lines[i].number, "trc-too-sparse", "more omitted trailing cells than the file has bytes");
    }
    rows.add(std::span(cells).subspan(std::min<std::size_t>(2, cells.size())), lines[i].number);
  }
  if (static_cast<std::int64_t>(rows.frames()) != frame_count) {
    fail(3, "trc-frame-count", "NumFrames is " + std::to_string(frame_count) + " but " +
                                   std::to_string(rows.frames()) + " frames follow");
  }
  return rows.finish(std::move(labels), rate_hz);
}

std::string write_trc(const MarkerFrames<Millimetres>& markers, std::string_view file_name) {
  if (!markers.consistent()) throw std::invalid_argument("write_trc: inconsistent marker set");
  for (const std::string& label : markers.labels) {
    if (label.empty() || label.find_first_of("\t\r\n") != std::string::npos) {
      throw std::invalid_argument("write_trc: label \"" + label + "\" is empty or holds a tab or line break");
    }
  }
  const std::string rate = shortest_decimal(markers.frame_rate_hz);
  const std::string frames = std::to_string(markers.frame_count());
  std::string out = "PathFileType\t4\t(X/Y/Z)\t" + std::string(file_name) + "\n";
  out += "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n";
  out += rate + "\t" + rate + "\t" + frames + "\t" + std::to_string(markers.marker_count()) + "\tmm\t" +
         rate + "\t" + std::to_string(markers.first_frame) + "\t" + frames + "\n";
  out += "Frame#\tTime";
  for (const std::string& label : markers.labels) out += "\t" + label + "\t\t";
  out += "\n\t";
  for (Eigen::Index m = 1; m <= markers.marker_count(); ++m) {
    const std::string n = std::to_string(m);
    out += "\tX" + n + "\tY" + n + "\tZ" + n;
  }
  return out + "\n\n" + detail::marker_row_lines(markers, '\t');
}

}  // namespace fapcast
