// The Festival-format lexicon and word-count parsers: good entries, every named bad input with
// its golden error, and the whole festlex-cmu lexicon of the machine.
#include "support/bad_inputs.hpp"
#include "fapcast/corpus/syllabified_lexicon.hpp"

#include <gtest/gtest.h>

#include "fapcast/core/input_error.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fapcast {
namespace {

using fapcast::test::slurp;

const std::filesystem::path kLexiconData = std::filesystem::path(FAPCAST_TEST_DATA) / "lexicon";

TEST(FestivalLexicon, ParsesSyllablesStressAndSchwa) {
  const auto entries = parse_festival_lexicon(
      "MNCL\r\n(\"abandon\" nil (((ax) 0) ((b ae n) 1) ((d ax n) 0)))\r\n\n(\"a\\\"b\" n (((ey) 2)))", "x");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].word, "abandon");
  EXPECT_EQ(entries[0].part_of_speech, "nil");
  ASSERT_EQ(entries[0].syllables.size(), 3u);
  EXPECT_EQ(entries[0].syllables[0], (Syllable{{Phone::AX}, Stress::kNone}));
  EXPECT_EQ(entries[0].syllables[1], (Syllable{{Phone::B, Phone::AE, Phone::N}, Stress::kPrimary}));
  EXPECT_EQ(entries[1].word, "a\"b");
  EXPECT_EQ(entries[1].syllables[0].stress, Stress::kSecondary);
}

TEST(WordCounts, ParsesCommentsAndCounts) {
  const auto counts = parse_word_counts("# c\nyou\t10\nthe\t10\nof\t3\n", "x");
  EXPECT_EQ(counts, (std::vector<WordCount>{{"you", 10}, {"the", 10}, {"of", 3}}));
}

// Every file in tests/data/lexicon/bad is refused with the rule in its name; the messages
// together equal the golden list expected_errors.txt.
TEST(LexiconBadInputs, EachIsRefusedWithItsRuleAndGoldenMessage) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(kLexiconData / "bad")) {
    if (e.path().filename().string().starts_with("bad.")) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 16u);
  std::string messages;
  for (const auto& f : files) {
    const std::string name = f.filename().string();
    const std::string rule = name.substr(8, name.rfind('.') - 8);  // bad.NNN.<rule>.<ext>
    try {
      if (f.extension() == ".tsv") parse_word_counts(slurp(f), name);
      else parse_festival_lexicon(slurp(f), name);
      ADD_FAILURE() << name << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(": " + rule + ": "), std::string::npos) << e.what();
      messages += std::string(e.what()) + "\n";
    }
  }
  EXPECT_EQ(messages, slurp(kLexiconData / "bad" / "expected_errors.txt"));
}

TEST(FestivalLexicon, WholeFestlexCmuParses) {
  const std::filesystem::path path = "/usr/share/festival/dicts/cmu/cmudict-0.4.out";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "festlex-cmu not installed";
  const auto entries = parse_festival_lexicon(slurp(path), path.string());
  EXPECT_GT(entries.size(), 100000u);
  for (const auto& e : entries) ASSERT_FALSE(e.syllables.empty()) << e.word;
}

TEST(WordCounts, VendoredSubtlexParsesAndIsSorted) {
  const auto counts = parse_word_counts(slurp(std::filesystem::path(FAPCAST_SOURCE_DIR) /
                                              "data/lexicon/subtlex-us-top20000.tsv"), "subtlex");
  ASSERT_EQ(counts.size(), 20000u);
  EXPECT_EQ(counts.front().word, "you");
}

}  // namespace
}  // namespace fapcast
