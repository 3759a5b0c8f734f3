#include "fapcast/corpus/lab_file.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"

#include "segment_rows.hpp"

#include <cmath>
#include <stdexcept>

namespace fapcast {
namespace {

constexpr double kHtkUnitsPerSecond = 1e7;  // HTK time unit: 100 ns

bool is_integer_spelling(std::string_view s) {
  if (s.starts_with('-') || s.starts_with('+')) s.remove_prefix(1);
  if (s.empty()) return false;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
  }
  return true;
}

// The order rule both directions share: times >= 0, start <= end, no overlap with the previous.
std::optional<std::string> order_problem(const std::vector<Interval>& segments, std::size_t i) {
  const Interval& s = segments[i];
  if (s.start_s < 0) return "segment starts before time 0";
  if (s.end_s < s.start_s) return "segment ends before it starts";
  if (i > 0 && s.start_s < segments[i - 1].end_s) return "segment overlaps the previous one";
  return std::nullopt;
}

// Seconds always spelled with a '.' or exponent, so that the reader cannot take them for HTK.
std::string seconds_spelling(double s) {
  std::string text = shortest_decimal(s);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

}  // namespace

LabFile read_lab(std::string_view bytes, const std::string& source, std::optional<LabTimeUnit> unit) {
  const std::string text = decode_text(bytes, source, "lab");
  const std::vector<TextLine> lines = split_lines(text);
  auto fail = [&](std::uint64_t line, const char* rule, const std::string& detail) {
    fail_at_line(source, line, rule, detail);
  };

  // First pass: shape of each line, and whether every time is an integer (HTK) or not.
  bool all_integer = true;
  std::int64_t segments = 0;
  for (const TextLine& line : lines) {
    const auto fields = split_whitespace(line.text);
    if (fields.empty()) continue;
    if (++segments > static_cast<std::int64_t>(detail::kMaxSegments))
      fail(line.number, "alignment-too-many-intervals",
           "more than " + std::to_string(detail::kMaxSegments) + " segments");
    if (fields[0] == "#!MLF!#") fail(line.number, "lab-mlf", "an HTK master label file, not a .lab");
    if (fields.size() == 1 && fields[0] == "///") {
      fail(line.number, "lab-alternatives", "HTK alternative transcriptions (///) are not supported");
    }
    if (fields.size() < 3 || fields.size() > 4) {
      fail(line.number, "lab-fields", "expected \"start end label [score]\", found " +
                                          std::to_string(fields.size()) + " fields");
    }
    all_integer = all_integer && is_integer_spelling(fields[0]) && is_integer_spelling(fields[1]);
  }

  LabFile lab;
  lab.unit = unit.value_or(all_integer ? LabTimeUnit::htk_100ns : LabTimeUnit::seconds);
  for (const TextLine& line : lines) {
    const auto fields = split_whitespace(line.text);
    if (fields.empty()) continue;
    Interval segment;
    double times[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const std::string_view f = fields[static_cast<std::size_t>(k)];
      const bool ok = lab.unit == LabTimeUnit::htk_100ns ? is_integer_spelling(f) && parse_finite(f, times[k])
                                                         : parse_finite(f, times[k]);
      if (!ok) {
        fail(line.number, "lab-bad-time",
             "\"" + excerpt(f) + "\" is not a time in " +
                 (lab.unit == LabTimeUnit::htk_100ns ? "100 ns units" : "seconds"));
      }
      if (lab.unit == LabTimeUnit::htk_100ns) times[k] /= kHtkUnitsPerSecond;
    }
    segment.start_s = times[0];
    segment.end_s = times[1];
    segment.label = std::string(fields[2]);
    std::optional<double> score;
    if (fields.size() == 4) {
      double s = 0;
      if (!parse_finite(fields[3], s)) {
        fail(line.number, "lab-bad-score", "\"" + excerpt(fields[3]) + "\" is not a number");
      }
      score = s;
    }
    lab.segments.push_back(std::move(segment));
    lab.scores.push_back(score);
    lab.lines.push_back(line.number);
    if (auto p = order_problem(lab.segments, lab.segments.size() - 1)) fail(line.number, "lab-interval-order", *p);
  }
  return lab;
}

std::string write_lab(const LabFile& lab) {
  if (lab.scores.size() != lab.segments.size() && !lab.scores.empty()) {
    throw std::invalid_argument("write_lab: scores must be empty or one per segment");
  }
  std::string out;
  for (std::size_t i = 0; i < lab.segments.size(); ++i) {
    const Interval& s = lab.segments[i];
    if (auto p = order_problem(lab.segments, i)) throw std::invalid_argument("write_lab: " + *p);
    if (s.label.empty() || s.label.find_first_of(" \t\r\n") != std::string::npos) {
      throw std::invalid_argument("write_lab: label \"" + s.label + "\" is empty or has whitespace");
    }
    if (lab.unit == LabTimeUnit::htk_100ns) {
      out += std::to_string(std::llround(s.start_s * kHtkUnitsPerSecond)) + " " +
             std::to_string(std::llround(s.end_s * kHtkUnitsPerSecond));
    } else {
      out += seconds_spelling(s.start_s) + " " + seconds_spelling(s.end_s);
    }
    out += " " + s.label;
    if (!lab.scores.empty() && lab.scores[i]) out += " " + shortest_decimal(*lab.scores[i]);
    out += "\n";
  }
  return out;
}

LabelTier to_tier(const LabFile& lab, std::string name) {
  LabelTier tier;
  tier.name = std::move(name);
  tier.kind = TierKind::intervals;
  tier.intervals = lab.segments;
  tier.end_s = lab.segments.empty() ? 0 : lab.segments.back().end_s;
  return tier;
}

}  // namespace fapcast
