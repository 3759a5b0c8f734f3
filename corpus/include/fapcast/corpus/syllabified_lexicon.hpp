#pragma once
// Syllabified pronunciations in Festival's lexicon format, as Debian's festlex-cmu ships CMUdict
// (/usr/share/festival/dicts/cmu/cmudict-0.4.out): one entry per line,
//   ("abandon" nil (((ax) 0) ((b ae n) 1) ((d ax n) 0)))
// i.e. word, part of speech (or nil), then syllables as ((phones...) stress). An optional first
// line "MNCL" marks a compiled lexicon. Phones are ARPAbet in lower case (ax = AH0).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/phonetics/phone.hpp"

namespace fapcast {

struct Syllable {
  std::vector<Phone> phones;
  Stress stress = Stress::kNone;
  friend bool operator==(const Syllable&, const Syllable&) = default;
};

struct LexiconEntry {
  std::string word;            // as in the lexicon (lower case)
  std::string part_of_speech;  // "nil" when none
  std::vector<Syllable> syllables;
  friend bool operator==(const LexiconEntry&, const LexiconEntry&) = default;
};

// Longest entry line accepted (the longest in cmudict-0.4 is under 300 bytes).
inline constexpr std::size_t kMaxLexiconLineBytes = 4096;

// Parses a whole Festival lexicon. Throws InputError "<source>:<line>: <rule>: <detail>"
// for the first malformed line (rules: line-too-long, expected-entry, unterminated-string,
// unbalanced-parentheses, too-deep, bad-syllable, bad-stress, unknown-phone, trailing-text).
std::vector<LexiconEntry> parse_festival_lexicon(std::string_view text, std::string_view source);

// A word and how often it occurs (SUBTLEX-US counts), most frequent first.
struct WordCount {
  std::string word;
  std::uint64_t count;
  friend bool operator==(const WordCount&, const WordCount&) = default;
};

// Parses "word<TAB>count" lines ('#' starts a comment line). Throws InputError
// "<source>:<line>: <rule>: <detail>" (rules: expected-tab, empty-word, bad-count, not-sorted).
std::vector<WordCount> parse_word_counts(std::string_view text, std::string_view source);

}  // namespace fapcast
