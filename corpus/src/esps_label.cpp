#include "fapcast/corpus/esps_label.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"
#include "segment_rows.hpp"

#include <optional>

namespace fapcast {

LabelTier read_esps_label(std::string_view bytes, const std::string& source, std::string tier_name) {
  const std::string text = decode_text(bytes, source, "esps");
  const std::vector<TextLine> lines = split_lines(text);
  std::size_t i = 0;
  std::optional<char> separator;
  for (; i < lines.size(); ++i) {
    const std::string_view l = trim(lines[i].text);
    if (l == "#") break;
    const auto f = split_whitespace(l);
    if (f.empty()) continue;
    if (f[0] == "separator" || f[0] == "seperator") {  // "seperator": EHMM's spelling in festvox
      if (f.size() != 2 || f[1].size() != 1) {
        fail_at_line(source, lines[i].number, "esps-header", "separator must be one character");
      }
      separator = f[1][0];
    }
  }
  if (i == lines.size()) {
    fail_at_line(source, lines.empty() ? 1 : lines.back().number, "esps-header",
                 "no line \"#\" ends the header (ESPS/xlabel files have one, even when the header is empty)");
  }
  LabelTier t;
  t.name = std::move(tier_name);
  double previous_end = 0;
  for (++i; i < lines.size(); ++i) {
    const std::string_view row = trim(lines[i].text);
    if (row.empty()) continue;
    const auto f = split_whitespace(row);
    double end = 0;
    if (!parse_finite(f[0], end)) {
      fail_at_line(source, lines[i].number, "esps-bad-time", "\"" + excerpt(f[0]) + "\" is not a time in seconds");
    }
    std::int64_t colour = 0;
    if (f.size() < 2 || !detail::parse_signed(f[1], colour)) {
      fail_at_line(source, lines[i].number, "esps-fields",
                   "expected \"END_TIME COLOUR LABEL\", the colour (an integer) is missing");
    }
    // The label: the row after the colour field, up to the separator when the header sets one.
    std::string_view label = trim(row.substr(static_cast<std::size_t>(f[1].data() + f[1].size() - row.data())));
    if (separator) label = trim(label.substr(0, label.find(*separator)));
    t.intervals.push_back({previous_end, end, std::string(label)});
    detail::check_segment_order(t, source, lines[i].number, "esps-time-order");
    previous_end = end;
  }
  detail::close_segment_tier(t);
  return t;
}

}  // namespace fapcast
