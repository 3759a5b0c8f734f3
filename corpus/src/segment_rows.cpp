#include "segment_rows.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"

#include <cstdio>

namespace fapcast::detail {




bool parse_signed(std::string_view s, std::int64_t& v) {
  const bool negative = s.starts_with('-');
  if (negative || s.starts_with('+')) s.remove_prefix(1);
  if (!parse_count(s, v)) return false;
  if (negative) v = -v;
  return true;
}

std::string time_text(double s) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6f", s);
  std::string t(buf);
  while (t.back() == '0') t.pop_back();
  if (t.back() == '.') t.pop_back();
  return t;
}

void check_segment_order(const LabelTier& t, const std::string& source, std::uint64_t line, const std::string& rule) {
  const Interval& v = t.intervals.back();
  if (v.start_s < 0) fail_at_line(source, line, rule, "segment starts before time 0");
  if (v.end_s < v.start_s) {
    fail_at_line(source, line, rule, "segment ends (" + time_text(v.end_s) + " s) before it starts (" +
                                         time_text(v.start_s) + " s)");
  }
  if (t.intervals.size() > 1 && v.start_s < t.intervals[t.intervals.size() - 2].end_s) {
    fail_at_line(source, line, rule, "segment starts (" + time_text(v.start_s) +
                                         " s) before the previous one ends (" +
                                         time_text(t.intervals[t.intervals.size() - 2].end_s) + " s)");
  }
  if (t.intervals.size() > kMaxSegments) {
    fail_at_line(source, line, rule, "more than " + std::to_string(kMaxSegments) + " segments");
  }
}

void close_segment_tier(LabelTier& t) {
  t.kind = TierKind::intervals;
  t.start_s = 0;
  t.end_s = t.intervals.empty() ? 0 : t.intervals.back().end_s;
}


}  // namespace fapcast::detail
