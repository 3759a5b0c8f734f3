#include "fapcast/corpus/htk_mlf.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"
#include "segment_rows.hpp"

namespace fapcast {

bool mlf_pattern_matches(std::string_view pattern, std::string_view stem) {
  if (const auto slash = pattern.find_last_of("/\\"); slash != std::string_view::npos) {
    pattern.remove_prefix(slash + 1);
  }
  if (const auto dot = pattern.rfind('.'); dot != std::string_view::npos) pattern = pattern.substr(0, dot);
  // glob with * and ?, iterative with one backtrack point
  std::size_t p = 0, s = 0, star = std::string_view::npos, mark = 0;
  while (s < stem.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == stem[s])) {
      ++p, ++s;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++, mark = s;
    } else if (star != std::string_view::npos) {
      p = star + 1, s = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::vector<MlfEntry> read_mlf(std::string_view bytes, const std::string& source) {
  const std::string text = decode_text(bytes, source, "mlf");
  const std::vector<TextLine> lines = split_lines(text);
  std::size_t i = 0;
  while (i < lines.size() && trim(lines[i].text).empty()) ++i;
  if (i == lines.size() || trim(lines[i].text) != "#!MLF!#") {
    fail_at_line(source, i < lines.size() ? lines[i].number : 1, "mlf-header", "the first line is not #!MLF!#");
  }
  std::vector<MlfEntry> entries;
  for (++i; i < lines.size(); ++i) {
    const std::string_view head = trim(lines[i].text);
    if (head.empty()) continue;
    if (!head.starts_with('"')) {
      fail_at_line(source, lines[i].number, "mlf-syntax", "expected a quoted file pattern, found \"" + excerpt(head) + "\"");
    }
    const std::size_t close = head.find('"', 1);
    if (close == std::string_view::npos) {
      fail_at_line(source, lines[i].number, "mlf-syntax", "the file pattern has no closing quote");
    }
    MlfEntry e;
    e.pattern = std::string(head.substr(1, close - 1));
    e.line = lines[i].number;
    const std::string_view rest = trim(head.substr(close + 1));
    if (rest.starts_with("->") || rest.starts_with("=>")) {
      fail_at_line(source, lines[i].number, "mlf-redirect",
                   "entry \"" + excerpt(e.pattern) + "\" points to the directory " + excerpt(trim(rest.substr(2))) +
                       ": fapcast reads only the labels an MLF holds itself");
    }
    if (!rest.empty()) {
      fail_at_line(source, lines[i].number, "mlf-syntax", "\"" + excerpt(rest) + "\" after the file pattern");
    }
    e.tier.name = e.pattern;
    bool closed = false;
    for (++i; i < lines.size(); ++i) {
      const std::string_view l = trim(lines[i].text);
      if (l == ".") {
        closed = true;
        break;
      }
      if (l.empty()) continue;
      if (l == "///") {
        fail_at_line(source, lines[i].number, "lab-alternatives",
                     "HTK alternative transcriptions (///): fapcast reads one alignment per entry");
      }
      const auto f = split_whitespace(l);
      std::int64_t start = 0, end = 0;
      if (f.size() < 3 || !detail::parse_signed(f[0], start) || !detail::parse_signed(f[1], end)) {
        fail_at_line(source, lines[i].number, "mlf-untimed",
                     "label line \"" + excerpt(l) + "\" has no start and end times (a transcription, not an alignment)");
      }
      // f[2] is the level-1 label; what follows are its score and auxiliary labels (HVite -m / -f)
      // with optional scores: numbers and words, both allowed, neither used.
      e.tier.intervals.push_back({static_cast<double>(start) * 1e-7, static_cast<double>(end) * 1e-7, std::string(f[2])});
      detail::check_segment_order(e.tier, source, lines[i].number, "lab-interval-order");
    }
    if (!closed) {
      fail_at_line(source, lines.back().number, "mlf-syntax", "entry \"" + excerpt(e.pattern) + "\" has no closing \".\" line");
    }
    detail::close_segment_tier(e.tier);
    entries.push_back(std::move(e));
  }
  return entries;
}

}  // namespace fapcast
