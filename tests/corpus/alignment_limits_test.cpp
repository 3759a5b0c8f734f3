// Issue #17, attack 9: 1.3 x 10^7 alignment intervals took 1.97 GB and exit 0. Every count an
// alignment file claims, and every segment it holds, is bounded (rule
// alignment-too-many-intervals) far above real files (the vendored ones pass in their own tests).
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/lab_file.hpp"
#include "fapcast/corpus/textgrid.hpp"
#include "corpus/corpus_test_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace fapcast {
namespace {

std::string rule_of(const auto& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.rule() + " | " + e.what();
  }
  return "no error";
}

std::string textgrid_claiming(const std::string& first_count, const std::string& second_count) {
  return "File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\nxmin = 0\nxmax = 1\n"
         "tiers? <exists>\nsize = 2\nitem []:\n"
         "    item [1]:\n        class = \"IntervalTier\"\n        name = \"phones\"\n"
         "        xmin = 0\n        xmax = 1\n        intervals: size = " + first_count + "\n"
         "        intervals [1]:\n            xmin = 0\n            xmax = 1\n            text = \"a\"\n"
         "    item [2]:\n        class = \"IntervalTier\"\n        name = \"words\"\n"
         "        xmin = 0\n        xmax = 1\n        intervals: size = " + second_count + "\n"
         "        intervals [1]:\n            xmin = 0\n            xmax = 1\n            text = \"a\"\n";
}

TEST(AlignmentLimits, ATextGridClaimingTooManyIntervalsIsRefusedAtTheCount) {
  EXPECT_EQ(rule_of([] { (void)read_textgrid(textgrid_claiming("1", "1"), "ok.TextGrid"); }), "no error");
  const std::string huge = rule_of([] { (void)read_textgrid(textgrid_claiming("13000000", "1"), "huge.TextGrid"); });
  EXPECT_TRUE(huge.starts_with("alignment-too-many-intervals | huge.TextGrid:14:")) << huge;
  // Two tiers (2), 1 interval and 2^21: each count within the bound, together over it.
  const std::string both = rule_of([] { (void)read_textgrid(textgrid_claiming("1", "2097152"), "two.TextGrid"); });
  EXPECT_TRUE(both.starts_with("alignment-too-many-intervals | two.TextGrid:")) << both;
}

TEST(AlignmentLimits, TheChronologicalAndBinaryFormsAreBoundedToo) {
  const std::string chronological = "\"Praat chronological TextGrid text file\"\n0 1\n3000000\n";
  const std::string c = rule_of([&] { (void)read_textgrid(chronological, "c.TextGrid"); });
  EXPECT_TRUE(c.starts_with("alignment-too-many-intervals | c.TextGrid:3:")) << c;
  // A real binary TextGrid (one tier) whose tier count, at byte 38, is made 2^31 - 1.
  std::string binary = test::file_bytes(std::filesystem::path(FAPCAST_TEST_DATA) /
                                        "alignment/textgrid/praat-binary/bobby_phones.binary.TextGrid");
  ASSERT_GT(binary.size(), 42u);
  ASSERT_EQ(binary.substr(38, 4), std::string("\0\0\0\1", 4));
  EXPECT_EQ(rule_of([&] { (void)read_textgrid(binary, "b.TextGrid"); }), "no error");
  binary.replace(38, 4, "\x7f\xff\xff\xff");
  const std::string b = rule_of([&] { (void)read_textgrid(binary, "b.TextGrid"); });
  EXPECT_TRUE(b.starts_with("alignment-too-many-intervals | b.TextGrid: byte 38:")) << b;
}

TEST(AlignmentLimits, ALabWithTooManySegmentsIsRefused) {
  std::string lab;
  const std::size_t lines = (std::size_t{1} << 21) + 1;
  lab.reserve(lines * 6);
  for (std::size_t i = 0; i < lines; ++i) lab += "0 1 a\n";
  const std::string r = rule_of([&] { (void)read_lab(lab, "huge.lab"); });
  EXPECT_TRUE(r.starts_with("alignment-too-many-intervals | huge.lab:" + std::to_string(lines) + ":")) << r;
}

}  // namespace
}  // namespace fapcast
