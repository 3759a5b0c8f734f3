#include "fapcast/corpus/bas_partitur.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"
#include "segment_rows.hpp"

#include <optional>

namespace fapcast {

Alignment read_partitur(std::string_view bytes, const std::string& source) {
  const std::string text = decode_text(bytes, source, "partitur");
  std::optional<std::int64_t> sam;
  struct Word {
    std::string text;
    double start = 0, end = 0;
    bool timed = false;
  };
  std::vector<Word> words;  // by ORT index
  LabelTier mau;
  mau.name = "MAU";
  std::vector<std::int64_t> links;
  std::vector<std::uint64_t> mau_lines;
  for (const TextLine& line : split_lines(text)) {
    const std::string_view l = trim(line.text);
    if (l.empty()) continue;
    const std::size_t colon = l.find(':');
    if (colon != 3) {
      fail_at_line(source, line.number, "partitur-syntax", "expected \"KEY: ...\" with a three-letter key, found \"" + excerpt(l) + "\"");
    }
    const std::string_view key = l.substr(0, 3);
    const auto f = split_whitespace(l.substr(4));
    if (key == "SAM") {
      std::int64_t rate = 0;
      if (f.size() != 1 || !parse_count(f[0], rate) || rate == 0) {
        fail_at_line(source, line.number, "partitur-header", "SAM (the sample rate) must be a positive integer");
      }
      sam = rate;
    } else if (key == "ORT") {
      std::int64_t index = 0;
      if (f.size() < 2 || !parse_count(f[0], index) || static_cast<std::size_t>(index) != words.size()) {
        fail_at_line(source, line.number, "partitur-syntax",
                     "ORT lines must be \"ORT: N WORD\" numbered 0, 1, 2 ... in order (expected " + std::to_string(words.size()) + ")");
      }
      words.push_back({std::string(f[1]), 0, 0, false});
    } else if (key == "MAU") {
      if (!sam) fail_at_line(source, line.number, "partitur-header", "MAU before SAM: the sample rate is not known");
      std::int64_t begin = 0, duration = 0, link = 0;
      if (f.size() < 4 || !parse_count(f[0], begin) || !parse_count(f[1], duration) ||
          !detail::parse_signed(f[2], link)) {
        fail_at_line(source, line.number, "partitur-syntax", "expected \"MAU: BEGIN DURATION WORD LABEL\" (samples, word index or -1)");
      }
      const double rate = static_cast<double>(*sam);
      mau.intervals.push_back({static_cast<double>(begin) / rate, static_cast<double>(begin + duration + 1) / rate,
                               std::string(f[3])});
      detail::check_segment_order(mau, source, line.number, "partitur-order");
      links.push_back(link);
      mau_lines.push_back(line.number);
    }
    // every other tier (KAN, TRN, SAP, ...) and header key is read past
  }
  if (!sam) fail_at_line(source, 1, "partitur-header", "no SAM line: the sample rate is not known");
  for (std::size_t k = 0; k < links.size(); ++k) {
    if (links[k] < 0) continue;
    if (static_cast<std::size_t>(links[k]) >= words.size()) {
      fail_at_line(source, mau_lines[k], "partitur-link", "MAU segment names word " + std::to_string(links[k]) +
                                                               ", but ORT has " + std::to_string(words.size()) + (words.size() == 1 ? " word" : " words"));
    }
    Word& w = words[static_cast<std::size_t>(links[k])];
    if (!w.timed) w.start = mau.intervals[k].start_s;
    w.end = mau.intervals[k].end_s;
    w.timed = true;
  }
  detail::close_segment_tier(mau);
  LabelTier ort;
  ort.name = "ORT";
  for (const Word& w : words) {
    if (w.timed) ort.intervals.push_back({w.start, w.end, w.text});
  }
  detail::close_segment_tier(ort);
  ort.end_s = mau.end_s;
  Alignment a;
  a.start_s = 0;
  a.end_s = mau.end_s;
  a.tiers.push_back(std::move(ort));
  a.tiers.push_back(std::move(mau));
  return a;
}

}  // namespace fapcast
