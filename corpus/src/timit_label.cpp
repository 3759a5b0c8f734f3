#include "fapcast/corpus/timit_label.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"
#include "segment_rows.hpp"

#include <stdexcept>

namespace fapcast {

LabelTier read_timit_label(std::string_view bytes, const std::string& source, SampleRate sample_rate,
                           std::string tier_name) {
  if (!sample_rate.valid()) throw std::invalid_argument("read_timit_label: sample rate must be positive");
  const std::string text = decode_text(bytes, source, "timit");
  LabelTier t;
  t.name = std::move(tier_name);
  const double rate = static_cast<double>(sample_rate.hz);
  for (const TextLine& line : split_lines(text)) {
    const auto f = split_whitespace(line.text);
    if (f.empty()) continue;
    if (f.size() != 3) {
      fail_at_line(source, line.number, "timit-fields",
                   "expected \"BEGIN END LABEL\" (3 fields), found " + std::to_string(f.size()));
    }
    std::int64_t begin = 0, end = 0;
    if (!parse_count(f[0], begin) || !parse_count(f[1], end)) {
      fail_at_line(source, line.number, "timit-bad-sample",
                   "\"" + excerpt(parse_count(f[0], begin) ? f[1] : f[0]) + "\" is not a sample number");
    }
    t.intervals.push_back({static_cast<double>(begin) / rate, static_cast<double>(end) / rate, std::string(f[2])});
    detail::check_segment_order(t, source, line.number, "timit-order");
  }
  detail::close_segment_tier(t);
  return t;
}

}  // namespace fapcast
