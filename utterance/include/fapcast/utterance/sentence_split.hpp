#pragma once
// A text cut into sentences, so that speaking can start after the first one is synthesised
// instead of after the whole text (spec/serve.md, "Sentence by sentence"). A minimal rule: a
// sentence ends after '.', '!', '?' or ';' (a run of them, then any closing quotes or brackets)
// that is followed by white space or the end, and at every line break that ends a paragraph
// (an empty line). A piece longer than max_bytes is cut at its last white space before the
// limit (a comma's if there is one), else at the limit on a UTF-8 boundary, so that no sentence
// keeps the first sound waiting. Abbreviations ("Dr.") end a sentence too: the only cost is a
// pause espeak-ng would have made shorter.
#include <cstddef>
#include <string_view>
#include <vector>

namespace fapcast {

struct SentenceSpan {
  std::size_t offset = 0;  // byte offset in the text
  std::size_t length = 0;  // bytes, white space around the sentence excluded
  bool operator==(const SentenceSpan&) const = default;
};

inline constexpr std::size_t kDefaultMaxSentenceBytes = 400;

// The sentences of `text` in order; white space between them is not part of any. Empty or
// all-white text gives none. max_bytes >= 8.
std::vector<SentenceSpan> split_sentences(std::string_view text, std::size_t max_bytes = kDefaultMaxSentenceBytes);

}  // namespace fapcast
