#include "fapcast/recognise/transcript.hpp"

#include <gtest/gtest.h>

#include <string>

#include "fapcast/core/input_error.hpp"

namespace fapcast {
namespace {

TEST(Transcript, WordsWithTheirByteOffsetsAndDictionaryKeys) {
  const Transcript t = parse_transcript("He turned sharply, and faced Gregson's  table.\n", "t.txt");
  ASSERT_EQ(t.words.size(), 7u);
  EXPECT_EQ(t.words[0], (TranscriptWord{"He", "he", 0}));
  EXPECT_EQ(t.words[2], (TranscriptWord{"sharply", "sharply", 10}));
  EXPECT_EQ(t.words[5], (TranscriptWord{"Gregson's", "gregson's", 29}));  // an apostrophe inside a word
  EXPECT_EQ(t.words[6], (TranscriptWord{"table", "table", 40}));
}

TEST(Transcript, AnApostropheAtAWordsEndSeparates) {
  const Transcript t = parse_transcript("the boys' 'game'", "t.txt");
  ASSERT_EQ(t.words.size(), 3u);
  EXPECT_EQ(t.words[1].text, "boys");
  EXPECT_EQ(t.words[2].text, "game");
  EXPECT_EQ(t.words[2].byte_offset, 11u);
}

TEST(Transcript, NonAsciiLettersStayInTheWord) {
  const Transcript t = parse_transcript("caf\xc3\xa9 na\xc3\xafve", "t.txt");
  ASSERT_EQ(t.words.size(), 2u);
  EXPECT_EQ(t.words[0].text, "caf\xc3\xa9");
  EXPECT_EQ(t.words[1].byte_offset, 6u);
}

// Typographic punctuation separates words as ASCII punctuation does; a typographic apostrophe
// inside a word is the dictionary's apostrophe.
TEST(Transcript, TypographicPunctuationSeparatesWords) {
  const Transcript t = parse_transcript("\u201cWait \u2014 don\u2019t\u2026\u201d\u00a0\u00abno\u00bb", "t.txt");
  ASSERT_EQ(t.words.size(), 3u);
  EXPECT_EQ(t.words[0], (TranscriptWord{"Wait", "wait", 3}));
  EXPECT_EQ(t.words[1], (TranscriptWord{"don\u2019t", "don't", 12}));
  EXPECT_EQ(t.words[2].key, "no");
}

TEST(Transcript, NoWordIsRefused) {
  try {
    (void)parse_transcript(" ... -- \n", "empty.txt");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "transcript-empty");
    EXPECT_STREQ(e.what(), "empty.txt: transcript-empty: no word to align");
  }
}

TEST(Transcript, BadTextIsRefusedNamingTheTranscriptAndTheByte) {
  try {
    (void)parse_transcript("good \xff bad", "bad.txt");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().source, "bad.txt");
    ASSERT_TRUE(e.where().offset.has_value());
    EXPECT_EQ(*e.where().offset, 5u);
    EXPECT_EQ(std::string(e.what()).rfind("bad.txt: byte 5: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace fapcast
