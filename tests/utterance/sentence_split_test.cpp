// The sentence rule of spec/serve.md: terminal punctuation before white space, empty lines, the
// byte cap cut at a comma or a space and never inside a UTF-8 code point.
#include "fapcast/utterance/sentence_split.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fapcast {
namespace {

std::vector<std::string> pieces(std::string_view text, std::size_t max = kDefaultMaxSentenceBytes) {
  std::vector<std::string> out;
  for (const SentenceSpan& s : split_sentences(text, max)) out.emplace_back(text.substr(s.offset, s.length));
  return out;
}

TEST(SentenceSplit, EndsAtTerminalPunctuationBeforeWhiteSpace) {
  EXPECT_EQ(pieces("Hello. How are you? Fine!  Thanks;  bye"),
            (std::vector<std::string>{"Hello.", "How are you?", "Fine!", "Thanks;", "bye"}));
  EXPECT_EQ(pieces("He said \"stop.\" Then left... Really?!"),
            (std::vector<std::string>{"He said \"stop.\"", "Then left...", "Really?!"}));
  EXPECT_EQ(pieces("Version 2.5 costs $3.50 today."), (std::vector<std::string>{"Version 2.5 costs $3.50 today."}));
  EXPECT_TRUE(pieces("").empty());
  EXPECT_TRUE(pieces(" \n\t ").empty());
}

TEST(SentenceSplit, OffsetsPointIntoTheText) {
  const std::string text = "  One.\n\nTwo three\n\n  four";
  const auto spans = split_sentences(text);
  ASSERT_EQ(spans.size(), 3u);
  EXPECT_EQ(spans[0], (SentenceSpan{2, 4}));
  EXPECT_EQ(text.substr(spans[1].offset, spans[1].length), "Two three");
  EXPECT_EQ(text.substr(spans[2].offset, spans[2].length), "four");
  EXPECT_EQ(pieces("a line\nand its continuation."), (std::vector<std::string>{"a line\nand its continuation."}));
}

TEST(SentenceSplit, LongPiecesAreCutAtACommaOrASpaceWithinTheCap) {
  EXPECT_EQ(pieces("one two three, four five six seven", 20),
            (std::vector<std::string>{"one two three,", "four five six seven"}));
  EXPECT_EQ(pieces("aaaa bbbb cccc dddd", 10), (std::vector<std::string>{"aaaa bbbb", "cccc dddd"}));
  // No space: cut at the cap, backing off to the start of a code point (é is 2 bytes).
  const std::string word = "abcdefg\xc3\xa9hij";
  EXPECT_EQ(pieces(word, 8), (std::vector<std::string>{"abcdefg", "\xc3\xa9hij"}));
  for (const auto& p : pieces(std::string(1000, 'x') + " end.", 64)) EXPECT_LE(p.size(), 64u);
}

}  // namespace
}  // namespace fapcast
