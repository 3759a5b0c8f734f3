#include "fapcast/corpus/textgrid.hpp"

#include "fapcast/core/input_error.hpp"
#include "corpus/corpus_test_support.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

using test::corpus_data;
using test::file_bytes;

Alignment two_tiers() {
  Alignment a;
  a.start_s = 0;
  a.end_s = 1.5;
  a.tiers.push_back({"phones", TierKind::intervals, 0, 1.5,
                     {{0, 0.1, ""}, {0.1, 0.75, "p"}, {0.75, 1.5, "say \"ah\""}}, {}});
  a.tiers.push_back({"bell", TierKind::points, 0, 1.5, {}, {{0.9, "ding"}}});
  return a;
}

TEST(TextGrid, LongFormIsPraatsLayout) {
  const std::string expected =
      "File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\n"
      "xmin = 0 \nxmax = 1.5 \ntiers? <exists> \nsize = 2 \nitem []: \n"
      "    item [1]:\n        class = \"IntervalTier\" \n        name = \"phones\" \n"
      "        xmin = 0 \n        xmax = 1.5 \n        intervals: size = 3 \n"
      "        intervals [1]:\n            xmin = 0 \n            xmax = 0.1 \n            text = \"\" \n"
      "        intervals [2]:\n            xmin = 0.1 \n            xmax = 0.75 \n            text = \"p\" \n"
      "        intervals [3]:\n            xmin = 0.75 \n            xmax = 1.5 \n"
      "            text = \"say \"\"ah\"\"\" \n"
      "    item [2]:\n        class = \"TextTier\" \n        name = \"bell\" \n"
      "        xmin = 0 \n        xmax = 1.5 \n        points: size = 1 \n"
      "        points [1]:\n            number = 0.9 \n            mark = \"ding\" \n";
  EXPECT_EQ(write_textgrid(two_tiers()), expected);
}

TEST(TextGrid, ShortFormIsValuesOnly) {
  const std::string text = write_textgrid(two_tiers(), TextGridForm::short_form);
  EXPECT_TRUE(text.starts_with("File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\n0\n1.5\n<exists>\n2\n"));
  EXPECT_EQ(text.find("xmin"), std::string::npos);
}

class TextGridRoundTrip : public ::testing::TestWithParam<TextGridForm> {};

TEST_P(TextGridRoundTrip, RandomAlignmentsReadBackExactly) {
  const std::uint64_t seed = test::test_seed(test::kCorpusSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 200; ++i) {
    const Alignment a = test::random_alignment(rng);
    const std::string text = write_textgrid(a, GetParam());
    const Alignment back = read_textgrid(text, "random.TextGrid");
    ASSERT_EQ(back, a) << "case " << i << "\n" << text;
    EXPECT_EQ(write_textgrid(back, GetParam()), text);  // writing is deterministic
  }
}

INSTANTIATE_TEST_SUITE_P(Forms, TextGridRoundTrip,
                         ::testing::Values(TextGridForm::long_form, TextGridForm::short_form),
                         [](const auto& info) { return info.param == TextGridForm::long_form ? "long" : "short"; });

TEST(TextGrid, LongAndShortFormsOfOneGridAgree) {
  EXPECT_EQ(read_textgrid(write_textgrid(two_tiers(), TextGridForm::long_form), "l"),
            read_textgrid(write_textgrid(two_tiers(), TextGridForm::short_form), "s"));
}

TEST(TextGrid, ReadsHandWrittenShortFormWithEscapedQuotes) {
  const Alignment a = read_textgrid(file_bytes(corpus_data() / "good/hand_short.TextGrid"), "hand_short");
  ASSERT_EQ(a.tiers.size(), 2u);
  const LabelTier* words = a.find("words");
  ASSERT_NE(words, nullptr);
  ASSERT_EQ(words->intervals.size(), 3u);
  EXPECT_EQ(words->intervals[1], (Interval{0.31, 0.98, "say \"hi\""}));
  const LabelTier* events = a.find("events");
  ASSERT_NE(events, nullptr);
  EXPECT_EQ(events->kind, TierKind::points);
  EXPECT_EQ(events->points, (std::vector<TimePoint>{{0.5, "click"}}));
  EXPECT_EQ(a.find("missing"), nullptr);
}

// The same IPA grid in every encoding and line ending Praat and editors produce.
class TextGridEncoding : public ::testing::TestWithParam<const char*> {};

TEST_P(TextGridEncoding, ReadsTheSameGrid) {
  const Alignment reference = read_textgrid(file_bytes(corpus_data() / "good/ipa.utf8bom.TextGrid"), "ref");
  const Alignment a = read_textgrid(file_bytes(corpus_data() / "good" / GetParam()), GetParam());
  EXPECT_EQ(a, reference);
  const LabelTier* phones = a.find("phones");
  ASSERT_NE(phones, nullptr);
  ASSERT_EQ(phones->intervals.size(), 3u);
  EXPECT_EQ(phones->intervals[0].label, "ʃ");
  EXPECT_EQ(phones->intervals[1].label, "iː");
  EXPECT_EQ(a.find("words")->intervals[0].label, "she 😀 \"quoted\"");
}

INSTANTIATE_TEST_SUITE_P(Files, TextGridEncoding,
                         ::testing::Values("ipa.utf16le.TextGrid", "ipa.utf16be.TextGrid",
                                           "ipa.utf8bom.TextGrid", "ipa.crlf.TextGrid"));

TEST(TextGrid, EmptyGridHasNoTiers) {
  Alignment a;
  a.end_s = 2;
  const std::string text = write_textgrid(a);
  EXPECT_NE(text.find("tiers? <absent>"), std::string::npos);
  EXPECT_EQ(read_textgrid(text, "empty"), a);
}

TEST(TextGrid, WriterRefusesWhatTheReaderWouldRefuse) {
  Alignment overlap = two_tiers();
  overlap.tiers[0].intervals[1].start_s = 0.05;
  EXPECT_THROW(write_textgrid(overlap), std::invalid_argument);
  Alignment reversed = two_tiers();
  reversed.end_s = -1;
  EXPECT_THROW(write_textgrid(reversed), std::invalid_argument);
  Alignment late_point = two_tiers();
  late_point.tiers[1].points[0].time_s = 7;
  EXPECT_THROW(write_textgrid(late_point), std::invalid_argument);
}

TEST(TextGrid, ErrorsNameFileLineAndRule) {
  try {
    read_textgrid("File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\n0\n1\n<maybe>\n", "x.TextGrid");
    FAIL() << "accepted a bad flag";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "textgrid-syntax");
    EXPECT_EQ(e.where().line, 6u);
    EXPECT_STREQ(e.what(), "x.TextGrid:6: textgrid-syntax: flag <maybe> is neither <exists> nor <absent>");
  }
}

TEST(TextGrid, EveryPrefixOfAValidFileIsRefusedCleanly) {
  const std::string text = write_textgrid(two_tiers(), TextGridForm::short_form);
  for (std::size_t n = 0; n + 1 < text.size(); ++n) {
    // A prefix may still be valid only if it ends inside the final newline; otherwise it throws.
    EXPECT_THROW(read_textgrid(text.substr(0, n), "prefix"), InputError) << n;
  }
}

TEST(TextGrid, SyntheticMarkSurvivesTheFile) {
  Alignment a = two_tiers();
  EXPECT_FALSE(is_synthetic(a));
  mark_synthetic(a);
  mark_synthetic(a);  // idempotent
  EXPECT_EQ(a.tiers.size(), 3u);
  EXPECT_TRUE(is_synthetic(read_textgrid(write_textgrid(a), "synthetic.TextGrid")));
}

TEST(LabelTier, SecondsToSamples) {
  EXPECT_EQ(to_sample(0.31, SampleRate{16000}), 4960);
  EXPECT_EQ(to_sample(1.0 / 32000, SampleRate{16000}), 1);  // half a sample rounds away from zero
  EXPECT_EQ(to_sample(-0.5, SampleRate{16000}), -8000);
  EXPECT_THROW(to_sample(1e300, SampleRate{16000}), std::out_of_range);
}

}  // namespace
}  // namespace fapcast
