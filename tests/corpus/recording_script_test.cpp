// The recording script: common words first by frequency, greedy syllable words, nonsense items
// that complete diviseme coverage; deterministic.
#include "support/bad_inputs.hpp"
#include "fapcast/corpus/recording_script.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace fapcast {
namespace {

using fapcast::test::slurp;

struct Mini {
  std::vector<WordCount> counts = parse_word_counts(
      slurp(std::filesystem::path(FAPCAST_TEST_DATA) / "lexicon/mini-word-counts.tsv"), "counts");
  std::vector<LexiconEntry> lexicon = parse_festival_lexicon(
      slurp(std::filesystem::path(FAPCAST_TEST_DATA) / "lexicon/mini-cmudict.out"), "lexicon");
};

TEST(Diviseme, IdsAreADenseBijection) {
  std::set<std::uint32_t> ids;
  for (std::size_t a = 0; a < kVisemeClassCount; ++a) {
    for (std::size_t b = 0; b < kVisemeClassCount; ++b) {
      if (a == 0 && b == 0) {
        EXPECT_THROW(diviseme_id(VisemeClass::kSilence, VisemeClass::kSilence), std::invalid_argument);
        continue;
      }
      const auto id = diviseme_id(static_cast<VisemeClass>(a), static_cast<VisemeClass>(b));
      EXPECT_LT(id, kDivisemeCount);
      ids.insert(id);
    }
  }
  EXPECT_EQ(ids.size(), kDivisemeCount);
}

TEST(Diviseme, UtteranceIsFramedBySilence) {
  const auto ids = divisemes_of({Phone::P, Phone::AA, Phone::P});
  ASSERT_EQ(ids.size(), 4u);
  EXPECT_EQ(ids.front(), diviseme_id(VisemeClass::kSilence, VisemeClass::kBilabial));
  EXPECT_EQ(ids[1], diviseme_id(VisemeClass::kBilabial, VisemeClass::kOpenUnrounded));
  EXPECT_EQ(ids.back(), diviseme_id(VisemeClass::kBilabial, VisemeClass::kSilence));
  EXPECT_TRUE(divisemes_of({}).empty());
}

TEST(RecordingScript, SectionsCoverageAndDeterminism) {
  const Mini mini;
  ScriptOptions options;
  options.common_words = 3;
  options.syllable_words = 5;
  const RecordingScript script = build_recording_script(mini.counts, mini.lexicon, options);
  // Common words: the three most frequent words that are in the lexicon, in order.
  ASSERT_GE(script.items.size(), 3u);
  EXPECT_EQ(script.items[0].text, "you");
  EXPECT_EQ(script.items[1].text, "the");
  EXPECT_EQ(script.items[2].text, "a");
  EXPECT_EQ(script.items[2].syllables[0].phones, std::vector<Phone>{Phone::AX});  // first entry wins
  std::size_t syllable_words = 0;
  double previous_gain = 1e300;
  std::set<std::string> texts;
  for (const auto& item : script.items) {
    EXPECT_TRUE(texts.insert(item.text).second) << "repeated " << item.text;
    if (item.section == ScriptSection::kSyllableWord) {
      ++syllable_words;
      EXPECT_GT(item.gain, 0.0);
      EXPECT_LE(item.gain, previous_gain);  // greedy gains never grow
      previous_gain = item.gain;
    }
    if (item.section == ScriptSection::kNonsense) {
      EXPECT_TRUE(item.espeak_phonemes.starts_with("[[")) << item.espeak_phonemes;
      EXPECT_GE(item.gain, 1.0);
    }
  }
  EXPECT_EQ(syllable_words, 5u);
  EXPECT_EQ(script.coverage.candidate_words, 18u);  // zzyzx is not in the lexicon
  EXPECT_EQ(script.coverage.divisemes_total_covered, kDivisemeCount);
  EXPECT_TRUE(script.coverage.uncovered_divisemes.empty());
  // Recount coverage from the items themselves.
  std::set<std::uint32_t> covered;
  for (const auto& item : script.items) {
    std::vector<Phone> phones;
    for (const auto& s : item.syllables) phones.insert(phones.end(), s.phones.begin(), s.phones.end());
    for (auto d : divisemes_of(phones)) covered.insert(d);
  }
  EXPECT_EQ(covered.size(), kDivisemeCount);
  EXPECT_EQ(format_recording_script(script),
            format_recording_script(build_recording_script(mini.counts, mini.lexicon, options)));
}

TEST(RecordingScript, AllWordsTakenCoverAllSyllables) {
  const Mini mini;
  ScriptOptions options;
  options.common_words = 0;
  options.syllable_words = 1000;
  const RecordingScript script = build_recording_script(mini.counts, mini.lexicon, options);
  EXPECT_EQ(script.coverage.covered_syllables, script.coverage.distinct_syllables);
  EXPECT_DOUBLE_EQ(script.coverage.syllable_token_share, 1.0);
}

}  // namespace
}  // namespace fapcast
