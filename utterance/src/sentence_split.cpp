#include "fapcast/utterance/sentence_split.hpp"

#include <algorithm>

namespace fapcast {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool is_terminal(char c) { return c == '.' || c == '!' || c == '?' || c == ';'; }
bool is_closing(char c) { return c == '"' || c == '\'' || c == ')' || c == ']' || c == '}'; }
bool is_continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// Appends [begin, end) trimmed, cut into pieces of at most max_bytes.
void emit(std::string_view text, std::size_t begin, std::size_t end, std::size_t max_bytes,
          std::vector<SentenceSpan>& out) {
  for (;;) {
    while (begin < end && is_space(text[begin])) ++begin;
    while (end > begin && is_space(text[end - 1])) --end;
    if (begin == end) return;
    if (end - begin <= max_bytes) {
      out.push_back({begin, end - begin});
      return;
    }
    const std::size_t limit = begin + max_bytes;
    std::size_t cut = 0;
    for (std::size_t i = limit; i > begin + 1; --i) {  // a comma followed by a space, else a space
      if (is_space(text[i]) && text[i - 1] == ',') {
        cut = i;
        break;
      }
    }
    if (cut == 0)
      for (std::size_t i = limit; i > begin; --i)
        if (is_space(text[i])) {
          cut = i;
          break;
        }
    if (cut == 0) {
      cut = limit;
      while (cut > begin + 1 && is_continuation(text[cut])) --cut;  // never inside a code point
    }
    out.push_back({begin, cut - begin});
    begin = cut;
    while (end > begin && is_space(text[end - 1])) --end;
  }
}

}  // namespace

std::vector<SentenceSpan> split_sentences(std::string_view text, std::size_t max_bytes) {
  max_bytes = std::max<std::size_t>(max_bytes, 8);
  std::vector<SentenceSpan> out;
  std::size_t start = 0, i = 0;
  while (i < text.size()) {
    if (is_terminal(text[i])) {
      std::size_t j = i;
      while (j < text.size() && is_terminal(text[j])) ++j;
      while (j < text.size() && is_closing(text[j])) ++j;
      if (j == text.size() || is_space(text[j])) {
        emit(text, start, j, max_bytes, out);
        start = i = j;
        continue;
      }
      i = j;
      continue;
    }
    if (text[i] == '\n') {  // an empty line ends a paragraph
      std::size_t j = i + 1;
      while (j < text.size() && (text[j] == ' ' || text[j] == '\t' || text[j] == '\r')) ++j;
      if (j < text.size() && text[j] == '\n') {
        emit(text, start, i, max_bytes, out);
        start = i = j;
        continue;
      }
    }
    ++i;
  }
  emit(text, start, text.size(), max_bytes, out);
  return out;
}

}  // namespace fapcast
