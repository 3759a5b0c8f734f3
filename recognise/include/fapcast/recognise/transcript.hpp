#pragma once
// What a recording says, as text: the words a forced alignment must find, each with its byte
// offset in the text (for messages and for espeak-ng's pronunciation of it). A word is a maximal
// run of letters, digits and apostrophes inside a word (ASCII letters and digits, and every
// non-ASCII code point); everything else separates words. spec/recognise.md, "Transcript".
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

struct TranscriptWord {
  std::string text;         // as written (UTF-8)
  std::string key;          // the dictionary key: ASCII letters lower-cased
  std::size_t byte_offset;  // where it starts in the text
  friend bool operator==(const TranscriptWord&, const TranscriptWord&) = default;
};

struct Transcript {
  std::string text;  // the whole text, validated
  std::vector<TranscriptWord> words;
};

// Checks `text` with the front-end's input rules (valid UTF-8, no control characters but TAB,
// LF, CR; validate_text) and splits it into words. Throws InputError "source: byte N: rule:
// detail" for bad text and rule "transcript-empty" when it has no word.
Transcript parse_transcript(std::string_view text, const std::string& source);

}  // namespace fapcast
