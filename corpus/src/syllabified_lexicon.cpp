#include "fapcast/corpus/syllabified_lexicon.hpp"

#include "fapcast/core/input_error.hpp"

#include <charconv>
#include <memory>
#include <stdexcept>

namespace fapcast {

namespace {

InputError line_error(std::string_view source, std::size_t line, std::string_view rule,
                      const std::string& detail) {
  return InputError({std::string(source), line, std::nullopt}, std::string(rule), detail);
}

// A parsed s-expression: an atom (string or symbol) or a list.
struct Sexp {
  bool is_list = false;
  bool is_string = false;
  std::string atom;
  std::vector<Sexp> items;
};

constexpr int kMaxDepth = 6;  // entry > syllables > syllable > phones: 4 levels used

class SexpParser {
 public:
  SexpParser(std::string_view text, std::string_view source, std::size_t line)
      : text_(text), source_(source), line_(line) {}

  Sexp parse_entry() {
    skip_space();
    if (pos_ >= text_.size() || text_[pos_] != '(') fail("expected-entry", "an entry starts with '('");
    Sexp entry = parse(0);
    skip_space();
    if (pos_ < text_.size()) fail("trailing-text", "text after the entry at byte " + std::to_string(pos_));
    return entry;
  }

 private:
  [[noreturn]] void fail(std::string_view rule, const std::string& detail) const {
    throw line_error(source_, line_, rule, detail);
  }
  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r')) ++pos_;
  }
  Sexp parse(int depth) {
    if (depth > kMaxDepth) fail("too-deep", "more than " + std::to_string(kMaxDepth) + " nested lists");
    skip_space();
    if (pos_ >= text_.size()) fail("unbalanced-parentheses", "entry ends inside a list");
    Sexp node;
    const char c = text_[pos_];
    if (c == '(') {
      node.is_list = true;
      ++pos_;
      for (;;) {
        skip_space();
        if (pos_ >= text_.size()) fail("unbalanced-parentheses", "missing ')'");
        if (text_[pos_] == ')') { ++pos_; break; }
        node.items.push_back(parse(depth + 1));
      }
    } else if (c == ')') {
      fail("unbalanced-parentheses", "unexpected ')' at byte " + std::to_string(pos_));
    } else if (c == '"') {
      node.is_string = true;
      ++pos_;
      for (;;) {
        if (pos_ >= text_.size()) fail("unterminated-string", "missing closing '\"'");
        const char d = text_[pos_++];
        if (d == '"') break;
        if (d == '\\') {
          if (pos_ >= text_.size()) fail("unterminated-string", "escape at end of line");
          node.atom.push_back(text_[pos_++]);
        } else {
          node.atom.push_back(d);
        }
      }
    } else {
      while (pos_ < text_.size() && text_[pos_] != ' ' && text_[pos_] != '\t' && text_[pos_] != '(' &&
             text_[pos_] != ')' && text_[pos_] != '"' && text_[pos_] != '\r') {
        node.atom.push_back(text_[pos_++]);
      }
    }
    return node;
  }

  std::string_view text_;
  std::string_view source_;
  std::size_t line_;
  std::size_t pos_ = 0;
};

LexiconEntry interpret_entry(const Sexp& e, std::string_view source, std::size_t line) {
  if (e.items.size() != 3 || !e.items[0].is_string || e.items[1].is_list || !e.items[2].is_list) {
    throw line_error(source, line, "expected-entry", "expected (\"word\" pos (syllables...))");
  }
  LexiconEntry entry{e.items[0].atom, e.items[1].atom, {}};
  if (entry.word.empty()) throw line_error(source, line, "expected-entry", "empty word");
  const std::string where = std::string(source) + ":" + std::to_string(line);
  for (const Sexp& syl : e.items[2].items) {
    if (!syl.is_list || syl.items.size() != 2 || !syl.items[0].is_list || syl.items[1].is_list) {
      throw line_error(source, line, "bad-syllable", "expected ((phones...) stress)");
    }
    const std::string& stress = syl.items[1].atom;
    if (stress != "0" && stress != "1" && stress != "2") {
      throw line_error(source, line, "bad-stress", "stress '" + stress + "' is not 0, 1 or 2");
    }
    Syllable s;
    s.stress = static_cast<Stress>(stress[0] - '0');
    for (const Sexp& ph : syl.items[0].items) {
      if (ph.is_list || ph.is_string) throw line_error(source, line, "bad-syllable", "a phone is a bare symbol");
      try {
        s.phones.push_back(parse_arpabet(ph.atom, where).phone);
      } catch (const std::invalid_argument&) {
        throw line_error(source, line, "unknown-phone", "'" + ph.atom + "'");
      }
      if (s.phones.back() == Phone::SIL) throw line_error(source, line, "unknown-phone", "'" + ph.atom + "'");
    }
    if (s.phones.empty()) throw line_error(source, line, "bad-syllable", "syllable without phones");
    entry.syllables.push_back(std::move(s));
  }
  if (entry.syllables.empty()) throw line_error(source, line, "bad-syllable", "word without syllables");
  return entry;
}

// Calls f(line_number, line) for each line (LF or CRLF), without the line end.
template <class F>
void for_each_line(std::string_view text, F&& f) {
  std::size_t line = 0;
  while (!text.empty()) {
    ++line;
    const std::size_t end = text.find('\n');
    std::string_view l = text.substr(0, end);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    f(line, l);
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
}

}  // namespace

std::vector<LexiconEntry> parse_festival_lexicon(std::string_view text, std::string_view source) {
  std::vector<LexiconEntry> entries;
  for_each_line(text, [&](std::size_t line, std::string_view l) {
    if (l.size() > kMaxLexiconLineBytes) {
      throw line_error(source, line, "line-too-long", std::to_string(l.size()) + " bytes, limit " +
                                                         std::to_string(kMaxLexiconLineBytes));
    }
    if (l.find_first_not_of(" \t") == std::string_view::npos) return;
    if (line == 1 && l == "MNCL") return;
    entries.push_back(interpret_entry(SexpParser(l, source, line).parse_entry(), source, line));
  });
  return entries;
}

std::vector<WordCount> parse_word_counts(std::string_view text, std::string_view source) {
  std::vector<WordCount> counts;
  for_each_line(text, [&](std::size_t line, std::string_view l) {
    if (l.empty() || l[0] == '#') return;
    const std::size_t tab = l.find('\t');
    if (tab == std::string_view::npos) throw line_error(source, line, "expected-tab", "expected word<TAB>count");
    if (tab == 0) throw line_error(source, line, "empty-word", "no word before the tab");
    const std::string_view number = l.substr(tab + 1);
    std::uint64_t count = 0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), count);
    if (ec != std::errc{} || end != number.data() + number.size() || number.empty()) {
      throw line_error(source, line, "bad-count", "'" + std::string(number) + "' is not a count");
    }
    if (!counts.empty() && count > counts.back().count) {
      throw line_error(source, line, "not-sorted", "counts must not increase");
    }
    counts.push_back({std::string(l.substr(0, tab)), count});
  });
  return counts;
}

}  // namespace fapcast
