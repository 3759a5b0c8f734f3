#include "fapcast/corpus/textgrid.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"

#include "segment_rows.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>

namespace fapcast {
namespace {


// A problem with one item of a tier, shared by the reader (which adds the line) and the writer.
struct Problem {
  std::string rule;
  std::string detail;
};

std::optional<Problem> check_span(double start_s, double end_s, const std::string& what) {
  if (!(start_s < end_s)) {
    return Problem{"textgrid-time-range", what + " has xmin " + shortest_decimal(start_s) +
                                              " not below xmax " + shortest_decimal(end_s)};
  }
  return std::nullopt;
}

std::optional<Problem> check_tier_span(const Alignment& grid, const LabelTier& tier) {
  if (auto p = check_span(tier.start_s, tier.end_s, "tier \"" + tier.name + "\"")) return p;
  if (tier.start_s < grid.start_s || tier.end_s > grid.end_s) {
    return Problem{"textgrid-time-range", "tier \"" + tier.name + "\" lies outside the TextGrid's [" +
                                              shortest_decimal(grid.start_s) + ", " +
                                              shortest_decimal(grid.end_s) + "]"};
  }
  return std::nullopt;
}

// Interval `i` of `tier` (the ones before it already checked): non-empty, after the previous
// one, inside the tier.
std::optional<Problem> check_interval(const LabelTier& tier, std::size_t i) {
  const Interval& v = tier.intervals[i];
  const std::string what = "interval " + std::to_string(i + 1) + " of tier \"" + tier.name + "\"";
  if (!(v.start_s < v.end_s)) {
    return Problem{"textgrid-interval-order", what + " is empty or reversed (" +
                                                  shortest_decimal(v.start_s) + " to " +
                                                  shortest_decimal(v.end_s) + ")"};
  }
  if (v.start_s < tier.start_s || v.end_s > tier.end_s) {
    return Problem{"textgrid-interval-order", what + " lies outside its tier"};
  }
  if (i > 0 && v.start_s < tier.intervals[i - 1].end_s) {
    return Problem{"textgrid-interval-order",
                   what + " starts at " + shortest_decimal(v.start_s) +
                       ", before the previous one ends (" +
                       shortest_decimal(tier.intervals[i - 1].end_s) + ")"};
  }
  return std::nullopt;
}

std::optional<Problem> check_point(const LabelTier& tier, std::size_t i) {
  const TimePoint& p = tier.points[i];
  const std::string what = "point " + std::to_string(i + 1) + " of tier \"" + tier.name + "\"";
  if (p.time_s < tier.start_s || p.time_s > tier.end_s) {
    return Problem{"textgrid-point-order", what + " lies outside its tier"};
  }
  if (i > 0 && !(p.time_s > tier.points[i - 1].time_s)) {
    return Problem{"textgrid-point-order", what + " is not after the previous point"};
  }
  return std::nullopt;
}

// ---- reading -------------------------------------------------------------------------------

enum class TokenKind { number, string, flag, end };

struct Token {
  TokenKind kind = TokenKind::end;
  std::string text;        // the number's spelling, the decoded string, or the flag's name
  std::string label;       // words before the value ("xmin =", "intervals [1]: xmin ="), spaced
  std::uint64_t line = 1;  // where the value starts
};

// Splits the TextGrid text into values (numbers, "strings", <flags>) and the key words before
// them. Both forms share it; the parser decides whether keys must be present (long) or absent.
class Tokenizer {
 public:
  Tokenizer(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  Token next() {
    Token t;
    for (;;) {
      skip_space();
      if (pos_ >= text_.size()) {
        t.line = line_;
        return t;
      }
      const char c = text_[pos_];
      if (c == '"') return string_token(std::move(t));
      if (c == '<') return flag_token(std::move(t));
      if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.') {
        t.kind = TokenKind::number;
        t.line = line_;
        t.text = std::string(word());
        return t;
      }
      if (!t.label.empty()) t.label += ' ';
      t.label += word();
    }
  }

 private:
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) line_ += text_[pos_++] == '\n';
  }
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
  std::string_view word() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != '"') ++pos_;
    return text_.substr(start, pos_ - start);
  }
  Token string_token(Token t) {
    t.kind = TokenKind::string;
    t.line = line_;
    ++pos_;
    for (;;) {
      if (pos_ >= text_.size()) {
        throw InputError({source_, t.line, std::nullopt}, "textgrid-unterminated-string",
                         "string has no closing quote");
      }
      const char c = text_[pos_++];
      if (c == '"') {
        if (pos_ < text_.size() && text_[pos_] == '"') {
          t.text += '"';  // "" inside a string is one quote
          ++pos_;
          continue;
        }
        if (pos_ < text_.size() && !is_space(text_[pos_])) {  // Praat: "end of string or undoubled quote?"
          throw InputError({source_, line_, std::nullopt}, "textgrid-syntax",
                           "'" + excerpt(text_.substr(pos_, 1)) + "' directly after a closing quote "
                           "(a quote inside a string is written \"\")");
        }
        return t;
      }
      line_ += c == '\n';
      t.text += c;
    }
  }
  Token flag_token(Token t) {
    t.kind = TokenKind::flag;
    t.line = line_;
    const std::string_view w = word();
    if (w.size() < 2 || w.back() != '>') {
      throw InputError({source_, line_, std::nullopt}, "textgrid-syntax",
                       "flag \"" + excerpt(w) + "\" has no closing '>'");
    }
    t.text = std::string(w.substr(1, w.size() - 2));
    return t;
  }

  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  std::uint64_t line_ = 1;
};

const char* kind_name(TokenKind kind) {
  switch (kind) {
    case TokenKind::number: return "a number";
    case TokenKind::string: return "a string";
    case TokenKind::flag: return "a <flag>";
    case TokenKind::end: return "the end of the file";
  }
  return "?";
}

// The tier kind a Praat class name stands for; nullopt for any other class.
std::optional<TierKind> tier_kind_of(std::string_view klass) {
  if (klass == "IntervalTier") return TierKind::intervals;
  if (klass == "TextTier") return TierKind::points;
  return std::nullopt;
}
std::string bad_tier_class(const std::string& which, std::string_view klass) {
  return which + " has class \"" + excerpt(klass) + "\", not IntervalTier or TextTier";
}

// The checks both text parsers make of a value token: present, of the kind wanted, a finite
// number, a count.
Token checked(Token t, TokenKind kind, const std::string& what, const std::string& source) {
  if (t.kind == TokenKind::end) {
    throw InputError({source, t.line, std::nullopt}, "textgrid-truncated", "the file ends before " + what);
  }
  if (t.kind != kind) {
    throw InputError({source, t.line, std::nullopt}, "textgrid-syntax",
                     "expected " + std::string(kind_name(kind)) + " for " + what + ", found " + kind_name(t.kind));
  }
  return t;
}
double token_number(const Token& t, const std::string& source) {
  double v = 0;
  if (!parse_finite(t.text, v)) {
    throw InputError({source, t.line, std::nullopt}, "textgrid-bad-number",
                     "\"" + excerpt(t.text) + "\" is not a finite number");
  }
  return v;
}
std::int64_t token_count(const Token& t, const std::string& what, const std::string& source) {
  std::int64_t n = 0;
  if (!parse_count(t.text, n)) {
    throw InputError({source, t.line, std::nullopt}, "textgrid-bad-count",
                     what + " \"" + excerpt(t.text) + "\" is not a count");
  }
  return n;  // never used to allocate: items are appended as they are read
}

// The tiers, intervals and points a file claims, all tiers together, against the bound of every
// alignment reader (detail::kMaxSegments; rule alignment-too-many-intervals), checked at each
// count before its items are read.
class ClaimedItems {
 public:
  void add(std::int64_t n, const InputLocation& at) {
    constexpr auto kMax = static_cast<std::int64_t>(detail::kMaxSegments);
    total_ += std::min(n, kMax + 1);
    if (n > kMax || total_ > kMax)
      throw InputError(at, "alignment-too-many-intervals",
                       "the file claims " + std::to_string(n > kMax ? n : total_) +
                           " tiers, intervals and points, more than " + std::to_string(kMax));
  }

 private:
  std::int64_t total_ = 0;
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& source) : tokens_(text, source), source_(source) {}

  Alignment parse() {
    const Token type = expect(TokenKind::string, "File type =", "the file type");
    if (type.text != "ooTextFile" && type.text != "ooTextFile short") {
      fail(type.line, "textgrid-header", "file type \"" + excerpt(type.text) + "\" is not ooTextFile");
    }
    const Token klass = expect(TokenKind::string, "Object class =", "the object class");
    if (klass.text != "TextGrid") {
      fail(klass.line, "textgrid-header", "object class \"" + excerpt(klass.text) + "\" is not TextGrid");
    }
    const Token first = next();
    long_form_ = !first.label.empty();  // the long form names every value; the short form none
    pending_ = first;

    Alignment grid;
    grid.start_s = number("xmin =", "the TextGrid's xmin");
    const Token end = expect(TokenKind::number, "xmax =", "the TextGrid's xmax");
    grid.end_s = to_double(end);
    if (auto p = check_span(grid.start_s, grid.end_s, "the TextGrid")) fail(end.line, *p);
    const Token tiers = expect(TokenKind::flag, "tiers?", "whether tiers exist");
    if (tiers.text == "exists") {
      const std::int64_t n = count("size =", "the number of tiers");
      claim(n);
      for (std::int64_t i = 0; i < n; ++i) grid.tiers.push_back(tier(grid, i + 1));
    } else if (tiers.text != "absent") {
      fail(tiers.line, "textgrid-syntax", "flag <" + excerpt(tiers.text) + "> is neither <exists> nor <absent>");
    }
    const Token rest = next();
    if (rest.kind != TokenKind::end || !rest.label.empty()) {
      fail(rest.line, "textgrid-trailing-data", "content after the last tier");
    }
    return grid;
  }

 private:
  LabelTier tier(const Alignment& grid, std::int64_t index) {
    const std::string which = "tier " + std::to_string(index);
    LabelTier t;
    const Token klass = expect(TokenKind::string, "class =", "the class of " + which);
    const std::optional<TierKind> kind = tier_kind_of(klass.text);
    if (!kind) fail(klass.line, "textgrid-tier-class", bad_tier_class(which, klass.text));
    t.kind = *kind;
    t.name = expect(TokenKind::string, "name =", "the name of " + which).text;
    t.start_s = number("xmin =", "the xmin of " + which);
    const Token end = expect(TokenKind::number, "xmax =", "the xmax of " + which);
    t.end_s = to_double(end);
    if (auto p = check_tier_span(grid, t)) fail(end.line, *p);
    if (t.kind == TierKind::intervals) {
      const std::int64_t n = count("intervals: size =", "the interval count of " + which);
      claim(n);
      for (std::int64_t i = 0; i < n; ++i) {
        Interval v;
        v.start_s = number("xmin =", "an interval's xmin");
        v.end_s = number("xmax =", "an interval's xmax");
        const Token text = expect(TokenKind::string, "text =", "an interval's text");
        v.label = text.text;
        t.intervals.push_back(std::move(v));
        if (auto p = check_interval(t, t.intervals.size() - 1)) fail(text.line, *p);
      }
    } else {
      const std::int64_t n = count("points: size =", "the point count of " + which);
      claim(n);
      for (std::int64_t i = 0; i < n; ++i) {
        TimePoint p;
        p.time_s = number("number =", "a point's time");
        const Token mark = expect(TokenKind::string, "mark =", "a point's mark");
        p.mark = mark.text;
        t.points.push_back(std::move(p));
        if (auto problem = check_point(t, t.points.size() - 1)) fail(mark.line, *problem);
      }
    }
    return t;
  }

  Token next() {
    if (pending_) {
      Token t = std::move(*pending_);
      pending_.reset();
      return t;
    }
    return tokens_.next();
  }

  // The next value, which must be of `kind` and (long form) follow words ending in `key`.
  Token expect(TokenKind kind, std::string_view key, const std::string& what) {
    Token t = checked(next(), kind, what, source_);
    const bool header = key == "File type =" || key == "Object class =";
    if (!header && long_form_ && !t.label.ends_with(key)) {
      fail(t.line, "textgrid-syntax", "expected \"" + std::string(key) + "\" before " + what +
                                          ", found \"" + excerpt(t.label) + "\"");
    }
    if (!header && !long_form_ && !t.label.empty()) {
      fail(t.line, "textgrid-syntax", "short-form TextGrid has words (\"" + excerpt(t.label) +
                                          "\") before " + what);
    }
    return t;
  }

  double to_double(const Token& t) { return token_number(t, source_); }
  double number(std::string_view key, const std::string& what) {
    return to_double(expect(TokenKind::number, key, what));
  }
  std::int64_t count(std::string_view key, const std::string& what) {
    const Token t = expect(TokenKind::number, key, what);
    count_line_ = t.line;
    return token_count(t, what, source_);
  }

  [[noreturn]] void fail(std::uint64_t line, const std::string& rule, const std::string& detail) {
    throw InputError({source_, line, std::nullopt}, rule, detail);
  }

  void claim(std::int64_t n) { claimed_.add(n, {source_, count_line_, std::nullopt}); }
  [[noreturn]] void fail(std::uint64_t line, const Problem& p) { fail(line, p.rule, p.detail); }

  Tokenizer tokens_;
  const std::string& source_;
  std::optional<Token> pending_;
  ClaimedItems claimed_;
  std::uint64_t count_line_ = 0;
  bool long_form_ = true;
};

// ---- Praat's chronological text form -------------------------------------------------------
// "Praat chronological TextGrid text file", the domain, the tier count, one line per tier
// (class, name, domain), then every interval and point in time order, each led by its 1-based
// tier number. '!' starts a comment that runs to the end of the line (Praat writes the tier name
// there). Real files: BAS WebMAUS output saved from Praat, Praat's own examples.
class ChronologicalParser {
 public:
  ChronologicalParser(std::string_view text, const std::string& source)
      : text_(strip_comments(text)), tokens_(text_, source), source_(source) {}

  Alignment parse() {
    const Token head = value(TokenKind::string, "the file type");
    if (head.text != "Praat chronological TextGrid text file") {
      fail(head.line, "textgrid-header", "\"" + excerpt(head.text) + "\" is not a chronological TextGrid");
    }
    Alignment grid;
    grid.start_s = number("the TextGrid's xmin");
    const Token end = value(TokenKind::number, "the TextGrid's xmax");
    grid.end_s = to_double(end);
    if (auto p = check_span(grid.start_s, grid.end_s, "the TextGrid")) fail(end.line, *p);
    const Token tier_count = value(TokenKind::number, "the number of tiers");
    const std::int64_t n = token_count(tier_count, "the number of tiers", source_);
    ClaimedItems claimed;
    claimed.add(n, {source_, tier_count.line, std::nullopt});
    for (std::int64_t i = 0; i < n; ++i) {
      const std::string which = "tier " + std::to_string(i + 1);
      LabelTier t;
      const Token klass = value(TokenKind::string, "the class of " + which);
      const std::optional<TierKind> kind = tier_kind_of(klass.text);
      if (!kind) fail(klass.line, "textgrid-tier-class", bad_tier_class(which, klass.text));
      t.kind = *kind;
      t.name = value(TokenKind::string, "the name of " + which).text;
      t.start_s = number("the xmin of " + which);
      const Token tend = value(TokenKind::number, "the xmax of " + which);
      t.end_s = to_double(tend);
      if (auto p = check_tier_span(grid, t)) fail(tend.line, *p);
      grid.tiers.push_back(std::move(t));
    }
    for (Token lead = tokens_.next(); lead.kind != TokenKind::end; lead = tokens_.next()) {
      std::int64_t k = 0;
      if (lead.kind != TokenKind::number || !parse_count(lead.text, k) || k < 1 || k > n) {
        fail(lead.line, "textgrid-syntax", "expected a tier number 1.." + std::to_string(n) + ", found " +
                                               (lead.kind == TokenKind::number ? "\"" + excerpt(lead.text) + "\""
                                                                               : kind_name(lead.kind)));
      }
      claimed.add(1, {source_, lead.line, std::nullopt});  // this form states no counts
      LabelTier& t = grid.tiers[static_cast<std::size_t>(k - 1)];
      if (t.kind == TierKind::intervals) {
        Interval v;
        v.start_s = number("an interval's xmin");
        v.end_s = number("an interval's xmax");
        const Token text = value(TokenKind::string, "an interval's text");
        v.label = text.text;
        t.intervals.push_back(std::move(v));
        if (auto p = check_interval(t, t.intervals.size() - 1)) fail(text.line, *p);
      } else {
        TimePoint p;
        p.time_s = number("a point's time");
        const Token mark = value(TokenKind::string, "a point's mark");
        p.mark = mark.text;
        t.points.push_back(std::move(p));
        if (auto problem = check_point(t, t.points.size() - 1)) fail(mark.line, *problem);
      }
    }
    return grid;
  }

 private:
  // '!' to the end of the line becomes spaces (outside strings), so that line numbers stay.
  static std::string strip_comments(std::string_view text) {
    std::string out(text);
    bool in_string = false;
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (out[i] == '"') {
        in_string = !in_string;  // a doubled quote toggles twice: still inside
      } else if (out[i] == '!' && !in_string) {
        while (i < out.size() && out[i] != '\n' && out[i] != '\r') out[i++] = ' ';
        --i;
      }
    }
    return out;
  }
  Token value(TokenKind kind, const std::string& what) {
    Token t = checked(tokens_.next(), kind, what, source_);
    if (!t.label.empty()) fail(t.line, "textgrid-syntax", "words (\"" + excerpt(t.label) + "\") before " + what);
    return t;
  }
  double to_double(const Token& t) { return token_number(t, source_); }
  double number(const std::string& what) { return to_double(value(TokenKind::number, what)); }
  [[noreturn]] void fail(std::uint64_t line, const std::string& rule, const std::string& detail) {
    throw InputError({source_, line, std::nullopt}, rule, detail);
  }
  [[noreturn]] void fail(std::uint64_t line, const Problem& p) { fail(line, p.rule, p.detail); }

  std::string text_;
  Tokenizer tokens_;
  const std::string& source_;
};

// ---- Praat's binary form ("ooBinaryFile") ---------------------------------------------------
// Layout (Praat's Data_writeToBinaryFile and TextGrid_def.h, all numbers big-endian):
// "ooBinaryFile", the class name as a 1-byte length + bytes ("TextGrid"), xmin, xmax (double),
// a byte 1 (tiers exist) or 0, the tier count (int32); per tier its class (1-byte length +
// bytes), its name (a "w16" string), xmin, xmax, the item count (int32) and the items: intervals
// as xmin, xmax, text; points as time, mark. A w16 string is a uint16 length and that many
// Latin-1 bytes, or 0xFFFF, a uint16 count of characters and their UTF-16 code units (a
// character outside the BMP takes two units but counts once).
class BinaryParser {
 public:
  BinaryParser(std::string_view bytes, const std::string& source) : b_(bytes), source_(source) {}

  Alignment parse() {
    if (b_.starts_with("ooBinary2File")) {
      fail(0, "textgrid-header", "a newer Praat binary format (ooBinary2File) than the one fapcast reads");
    }
    pos_ = std::string_view("ooBinaryFile").size();
    const std::size_t klass_at = pos_;
    const std::string klass = short_string("the object class");
    if (klass != "TextGrid") {
      fail(klass_at, "textgrid-header", "binary Praat file of class \"" + excerpt(klass) + "\", not TextGrid");
    }
    Alignment grid;
    grid.start_s = real("the TextGrid's xmin");
    const std::size_t end_at = pos_;
    grid.end_s = real("the TextGrid's xmax");
    if (auto p = check_span(grid.start_s, grid.end_s, "the TextGrid")) fail(end_at, *p);
    const std::size_t flag_at = pos_;
    const std::uint8_t exists = byte("whether tiers exist");
    if (exists == 1) {
      const std::int64_t n = count("the number of tiers");
      for (std::int64_t i = 0; i < n; ++i) grid.tiers.push_back(tier(grid, i + 1));
    } else if (exists != 0) {
      fail(flag_at, "textgrid-syntax", "tier flag byte " + std::to_string(exists) + " is neither 1 nor 0");
    }
    if (pos_ != b_.size()) fail(pos_, "textgrid-trailing-data", "content after the last tier");
    return grid;
  }

 private:
  LabelTier tier(const Alignment& grid, std::int64_t index) {
    const std::string which = "tier " + std::to_string(index);
    LabelTier t;
    const std::size_t klass_at = pos_;
    const std::string klass = short_string("the class of " + which);
    const std::optional<TierKind> kind = tier_kind_of(klass);
    if (!kind) fail(klass_at, "textgrid-tier-class", bad_tier_class(which, klass));
    t.kind = *kind;
    t.name = text("the name of " + which);
    t.start_s = real("the xmin of " + which);
    const std::size_t end_at = pos_;
    t.end_s = real("the xmax of " + which);
    if (auto p = check_tier_span(grid, t)) fail(end_at, *p);
    const std::int64_t n = count(t.kind == TierKind::intervals ? "the interval count of " + which
                                                               : "the point count of " + which);
    for (std::int64_t i = 0; i < n; ++i) {  // never used to allocate: items are appended as read
      const std::size_t at = pos_;
      if (t.kind == TierKind::intervals) {
        Interval v;
        v.start_s = real("an interval's xmin");
        v.end_s = real("an interval's xmax");
        v.label = text("an interval's text");
        t.intervals.push_back(std::move(v));
        if (auto p = check_interval(t, t.intervals.size() - 1)) fail(at, *p);
      } else {
        TimePoint p;
        p.time_s = real("a point's time");
        p.mark = text("a point's mark");
        t.points.push_back(std::move(p));
        if (auto problem = check_point(t, t.points.size() - 1)) fail(at, *problem);
      }
    }
    return t;
  }

  void need(std::size_t n, const std::string& what) {
    if (b_.size() - pos_ < n) fail(pos_, "textgrid-truncated", "the file ends before " + what);
  }
  std::uint8_t byte(const std::string& what) {
    need(1, what);
    return static_cast<std::uint8_t>(b_[pos_++]);
  }
  std::uint16_t u16(const std::string& what) {
    need(2, what);
    const auto hi = static_cast<std::uint8_t>(b_[pos_]), lo = static_cast<std::uint8_t>(b_[pos_ + 1]);
    pos_ += 2;
    return static_cast<std::uint16_t>(hi << 8 | lo);
  }
  std::int64_t count(const std::string& what) {
    need(4, what);
    const std::size_t at = pos_;
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = v << 8 | static_cast<std::uint8_t>(b_[pos_++]);
    const auto n = static_cast<std::int32_t>(v);
    if (n < 0) fail(at, "textgrid-bad-count", what + " " + std::to_string(n) + " is negative");
    claimed_.add(n, {source_, std::nullopt, at});
    return n;
  }
  double real(const std::string& what) {
    need(8, what);
    const std::size_t at = pos_;
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v = v << 8 | static_cast<std::uint8_t>(b_[pos_++]);
    double d = 0;
    static_assert(sizeof d == sizeof v);
    std::memcpy(&d, &v, sizeof d);
    if (!std::isfinite(d)) fail(at, "textgrid-bad-number", what + " is not a finite number");
    return d;
  }
  std::string short_string(const std::string& what) {
    const std::uint8_t n = byte(what);
    need(n, what);
    std::string s(b_.substr(pos_, n));
    pos_ += n;
    return s;
  }
  static void append_utf8(std::string& out, std::uint32_t c) {
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | c >> 6);
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | c >> 12);
      out += static_cast<char>(0x80 | (c >> 6 & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | c >> 18);
      out += static_cast<char>(0x80 | (c >> 12 & 0x3F));
      out += static_cast<char>(0x80 | (c >> 6 & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  std::string text(const std::string& what) {
    std::string out;
    std::uint16_t n = u16(what);
    if (n != 0xFFFF) {  // Latin-1 bytes
      need(n, what);
      for (std::size_t i = 0; i < n; ++i) append_utf8(out, static_cast<std::uint8_t>(b_[pos_ + i]));
      pos_ += n;
    } else {
      n = u16(what);
      for (std::uint16_t i = 0; i < n; ++i) {
        const std::size_t at = pos_;
        std::uint32_t c = u16(what);
        if ((c & 0xF800) == 0xD800) {
          const std::uint32_t c2 = c <= 0xDBFF ? u16(what) : 0;
          if (c2 < 0xDC00 || c2 > 0xDFFF) fail(at, "textgrid-encoding", what + " has an unpaired UTF-16 surrogate");
          c = ((c & 0x3FF) << 10 | (c2 & 0x3FF)) + 0x10000;
        }
        if (c == 0) fail(at, "textgrid-encoding", what + " has a NUL character");
        append_utf8(out, c);
      }
    }
    if (out.find('\0') != std::string::npos) fail(pos_, "textgrid-encoding", what + " has a NUL byte");
    return out;
  }
  [[noreturn]] void fail(std::size_t offset, const std::string& rule, const std::string& detail) {
    throw InputError({source_, std::nullopt, offset}, rule, detail);
  }
  [[noreturn]] void fail(std::size_t offset, const Problem& p) { fail(offset, p.rule, p.detail); }

  std::string_view b_;
  const std::string& source_;
  std::size_t pos_ = 0;
  ClaimedItems claimed_;
};

// ---- writing -------------------------------------------------------------------------------

std::string praat_quoted(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    out += c;
    if (c == '"') out += '"';
  }
  return out + "\"";
}

// Appends values either as Praat's long form ("key = value " lines, indented) or the short one.
class Writer {
 public:
  explicit Writer(TextGridForm form) : long_(form == TextGridForm::long_form) {}
  void line(int indent, std::string_view key, const std::string& value) {
    if (long_) {
      out_.append(static_cast<std::size_t>(indent) * 4, ' ');
      out_ += key;
      out_ += " = ";
    }
    out_ += value;
    out_ += long_ ? " \n" : "\n";
  }
  void heading(int indent, const std::string& text) {
    if (long_) out_.append(static_cast<std::size_t>(indent) * 4, ' ').append(text).append("\n");
  }
  void number(int indent, std::string_view key, double v) { line(indent, key, shortest_decimal(v)); }
  void flag(const char* value) {
    out_ += long_ ? "tiers? " : "";
    out_ += value;
    out_ += long_ ? " \n" : "\n";
  }
  std::string take() { return std::move(out_); }

 private:
  bool long_;
  std::string out_ = "File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\n";
};

[[noreturn]] void refuse(const Problem& p) {
  throw std::invalid_argument("write_textgrid: " + p.rule + ": " + p.detail);
}

}  // namespace

Alignment read_textgrid(std::string_view bytes, const std::string& source) {
  if (bytes.starts_with("ooBinaryFile") || bytes.starts_with("ooBinary2File")) {
    return BinaryParser(bytes, source).parse();
  }
  const std::string text = decode_text(bytes, source, "textgrid");
  if (trim(text).starts_with("\"Praat chronological TextGrid text file\"")) {
    return ChronologicalParser(text, source).parse();
  }
  return Parser(text, source).parse();
}

std::string write_textgrid(const Alignment& grid, TextGridForm form) {
  if (auto p = check_span(grid.start_s, grid.end_s, "the TextGrid")) refuse(*p);
  Writer w(form);
  w.number(0, "xmin", grid.start_s);
  w.number(0, "xmax", grid.end_s);
  if (grid.tiers.empty()) {
    w.flag("<absent>");
    return w.take();
  }
  w.flag("<exists>");
  w.line(0, "size", std::to_string(grid.tiers.size()));
  w.heading(0, "item []: ");
  for (std::size_t k = 0; k < grid.tiers.size(); ++k) {
    const LabelTier& tier = grid.tiers[k];
    if (auto p = check_tier_span(grid, tier)) refuse(*p);
    const bool intervals = tier.kind == TierKind::intervals;
    w.heading(1, "item [" + std::to_string(k + 1) + "]:");
    w.line(2, "class", praat_quoted(intervals ? "IntervalTier" : "TextTier"));
    w.line(2, "name", praat_quoted(tier.name));
    w.number(2, "xmin", tier.start_s);
    w.number(2, "xmax", tier.end_s);
    if (intervals) {
      w.line(2, "intervals: size", std::to_string(tier.intervals.size()));
      for (std::size_t i = 0; i < tier.intervals.size(); ++i) {
        if (auto p = check_interval(tier, i)) refuse(*p);
        w.heading(2, "intervals [" + std::to_string(i + 1) + "]:");
        w.number(3, "xmin", tier.intervals[i].start_s);
        w.number(3, "xmax", tier.intervals[i].end_s);
        w.line(3, "text", praat_quoted(tier.intervals[i].label));
      }
    } else {
      w.line(2, "points: size", std::to_string(tier.points.size()));
      for (std::size_t i = 0; i < tier.points.size(); ++i) {
        if (auto p = check_point(tier, i)) refuse(*p);
        w.heading(2, "points [" + std::to_string(i + 1) + "]:");
        w.number(3, "number", tier.points[i].time_s);
        w.line(3, "mark", praat_quoted(tier.points[i].mark));
      }
    }
  }
  return w.take();
}

}  // namespace fapcast
