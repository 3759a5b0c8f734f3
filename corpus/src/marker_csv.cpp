#include "fapcast/corpus/marker_csv.hpp"

#include "fapcast/core/input_error.hpp"
#include "marker_rows.hpp"
#include "fapcast/core/text_input.hpp"

#include <stdexcept>

namespace fapcast {

MarkerFrames<Millimetres> read_marker_csv(std::string_view bytes, const std::string& source) {
  const std::string text = decode_text(bytes, source, "csv");
  const std::vector<TextLine> lines = split_lines(text);
  auto fail = [&](std::uint64_t line, const char* rule, const std::string& detail) {
    fail_at_line(source, line, rule, detail);
  };
  std::optional<double> rate_hz;
  std::string units = "mm";
  std::size_t i = 0;
  for (; i < lines.size() && lines[i].text.starts_with('#'); ++i) {
    const std::string_view setting = trim(lines[i].text.substr(1));
    const std::size_t eq = setting.find('=');
    const std::string_view key = trim(setting.substr(0, eq));
    const std::string_view value = eq == std::string_view::npos ? "" : trim(setting.substr(eq + 1));
    if (key == "frame_rate_hz") {
      double r = 0;
      if (!parse_finite(value, r) || r <= 0) fail(lines[i].number, "csv-bad-rate", "frame_rate_hz must be a positive number");
      rate_hz = r;
    } else if (key == "units") {
      units = std::string(value);
    }  // other comments are ignored
  }
  const std::optional<double> mm = millimetres_per_unit(units);
  if (!mm) fail(i, "csv-units", "units \"" + excerpt(units) + "\" is not mm, cm, m or in");
  if (i >= lines.size()) fail(i + 1, "csv-header", "no header row");

  const auto header = split_fields(lines[i].text, ',');
  const std::uint64_t header_line = lines[i].number;
  if (header.size() < 2 || trim(header[0]) != "frame" || trim(header[1]) != "time_s") {
    fail(header_line, "csv-header", "the header must start with frame,time_s");
  }
  if ((header.size() - 2) % 3 != 0) fail(header_line, "csv-header", "coordinate columns do not come in x,y,z triples");
  std::vector<std::string> labels;
  for (std::size_t c = 2; c < header.size(); c += 3) {
    const std::string_view x = trim(header[c]);
    if (x.size() < 3 || !x.ends_with(".x")) fail(header_line, "csv-header", "column \"" + excerpt(x) + "\" is not LABEL.x");
    const std::string_view label = x.substr(0, x.size() - 2);
    if (trim(header[c + 1]) != std::string(label) + ".y" ||
        trim(header[c + 2]) != std::string(label) + ".z") {
      fail(header_line, "csv-header", "columns after " + excerpt(x) + " are not " +
                                          excerpt(label) + ".y," + excerpt(label) + ".z");
    }
    labels.emplace_back(label);
  }

  detail::MarkerRows rows(labels.size(), *mm, source, "csv");
  double first_time = 0;
  double last_time = 0;
  for (++i; i < lines.size(); ++i) {
    if (trim(lines[i].text).empty()) continue;
    const auto cells = split_fields(lines[i].text, ',');
    if (cells.size() != header.size()) {
      fail(lines[i].number, "csv-fields", std::to_string(cells.size()) + " cells, the header has " +
                                              std::to_string(header.size()));
    }
    std::int64_t frame = 0;
    double time = 0;
    if (!parse_count(trim(cells[0]), frame)) fail(lines[i].number, "csv-frame-number", "\"" + excerpt(cells[0]) + "\" is not a frame number");
    if (!parse_finite(trim(cells[1]), time)) fail(lines[i].number, "csv-bad-number", "time \"" + excerpt(cells[1]) + "\" is not a number");
    if (rows.frames() == 0) {
      first_time = time;
    } else if (!(time > last_time)) {
      fail(lines[i].number, "csv-time-order", "time does not increase");
    }
    rows.check_frame_number(frame, lines[i].number);
    last_time = time;
    rows.add(std::span(cells).subspan(2), lines[i].number);
  }
  if (!rate_hz) {
    if (rows.frames() < 2) fail(header_line, "csv-no-rate", "no frame_rate_hz setting and fewer than 2 frames to derive it");
    rate_hz = static_cast<double>(rows.frames() - 1) / (last_time - first_time);
  }
  return rows.finish(std::move(labels), *rate_hz);
}

std::string write_marker_csv(const MarkerFrames<Millimetres>& markers) {
  if (!markers.consistent()) throw std::invalid_argument("write_marker_csv: inconsistent marker set");
  std::string out = "# frame_rate_hz=" + shortest_decimal(markers.frame_rate_hz) + "\n# units=mm\nframe,time_s";
  for (const std::string& label : markers.labels) {
    if (label.empty() || label.find_first_of(",\"\r\n") != std::string::npos) {
      throw std::invalid_argument("write_marker_csv: label \"" + label + "\" is empty or holds , \" or a line break");
    }
    out += "," + label + ".x," + label + ".y," + label + ".z";
  }
  return out + "\n" + detail::marker_row_lines(markers, ',');
}

}  // namespace fapcast
