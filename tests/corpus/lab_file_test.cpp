#include "fapcast/corpus/lab_file.hpp"

#include "fapcast/core/input_error.hpp"
#include "corpus/corpus_test_support.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

using test::corpus_data;
using test::file_bytes;

TEST(LabFile, DetectsHtkUnitsAndScores) {
  const LabFile lab = read_lab(file_bytes(corpus_data() / "good/htk.lab"), "htk.lab");
  EXPECT_EQ(lab.unit, LabTimeUnit::htk_100ns);
  ASSERT_EQ(lab.segments.size(), 3u);
  EXPECT_EQ(lab.segments[1], (Interval{0.31, 0.4125, "dh"}));
  EXPECT_EQ(lab.scores, (std::vector<std::optional<double>>{-12.5, -30.25, -7.0}));
}

TEST(LabFile, DetectsMochaSeconds) {
  const LabFile lab = read_lab(file_bytes(corpus_data() / "good/mocha.lab"), "mocha.lab");
  EXPECT_EQ(lab.unit, LabTimeUnit::seconds);
  ASSERT_EQ(lab.segments.size(), 4u);
  EXPECT_EQ(lab.segments[0], (Interval{0.0, 0.31, "breath"}));
  EXPECT_EQ(lab.segments[3], (Interval{0.5, 0.675, "b"}));
  EXPECT_EQ(lab.scores, std::vector<std::optional<double>>(4));
}

TEST(LabFile, BothUnitsAgreeOnTheSameTimes) {
  const LabFile htk = read_lab(file_bytes(corpus_data() / "good/htk.lab"), "htk.lab");
  const LabFile mocha = read_lab(file_bytes(corpus_data() / "good/mocha.lab"), "mocha.lab");
  for (std::size_t i = 0; i < htk.segments.size(); ++i) {
    EXPECT_DOUBLE_EQ(htk.segments[i].end_s, mocha.segments[i].end_s);
  }
}

TEST(LabFile, ForcedUnitOverridesDetection) {
  // Integer times that are really seconds (a file of whole seconds).
  const LabFile lab = read_lab("0 1 sil\n1 2 a\n", "whole.lab", LabTimeUnit::seconds);
  EXPECT_EQ(lab.segments[1], (Interval{1.0, 2.0, "a"}));
  EXPECT_THROW(read_lab("0 0.5 a\n", "x.lab", LabTimeUnit::htk_100ns), InputError);
}

class LabRoundTrip : public ::testing::TestWithParam<LabTimeUnit> {};

TEST_P(LabRoundTrip, RandomSegmentsReadBack) {
  const std::uint64_t seed = test::test_seed(test::kCorpusSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  for (int round = 0; round < 100; ++round) {
    LabFile lab;
    lab.unit = GetParam();
    std::int64_t t = static_cast<std::int64_t>(rng() % 1000);  // 100 ns ticks, so HTK is exact
    const int n = static_cast<int>(rng() % 8);
    for (int i = 0; i < n; ++i) {
      const std::int64_t next = t + static_cast<std::int64_t>(rng() % 3000000);  // may be empty
      lab.segments.push_back({static_cast<double>(t) / 1e7, static_cast<double>(next) / 1e7,
                              "ph" + std::to_string(rng() % 50)});
      lab.scores.push_back(rng() % 2 ? std::optional<double>(-static_cast<double>(rng() % 10000) / 8) : std::nullopt);
      t = next + static_cast<std::int64_t>(rng() % 2) * 100;
    }
    const std::string text = write_lab(lab);
    ASSERT_EQ(read_lab(text, "r.lab", lab.unit), lab) << text;
    if (n > 0 && GetParam() == LabTimeUnit::seconds) {
      EXPECT_EQ(read_lab(text, "r.lab").unit, LabTimeUnit::seconds) << "detection must find seconds\n" << text;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Units, LabRoundTrip, ::testing::Values(LabTimeUnit::htk_100ns, LabTimeUnit::seconds),
                         [](const auto& info) { return info.param == LabTimeUnit::htk_100ns ? "htk" : "seconds"; });

TEST(LabFile, WriterRefusesLabelsWithSpaces) {
  LabFile lab;
  lab.segments.push_back({0, 1, "two words"});
  EXPECT_THROW(write_lab(lab), std::invalid_argument);
}

TEST(LabFile, ToTierSpansTheSegments) {
  const LabelTier tier = to_tier(read_lab(file_bytes(corpus_data() / "good/mocha.lab"), "m"), "phones");
  EXPECT_EQ(tier.name, "phones");
  EXPECT_EQ(tier.start_s, 0.0);
  EXPECT_EQ(tier.end_s, 0.675);
  EXPECT_EQ(tier.intervals.size(), 4u);
}

}  // namespace
}  // namespace fapcast
