// Praat's other TextGrid forms (binary, chronological) and Praat's own text I/O test files:
// texio1 is read, texio2..20 are refused at the line Praat's test/fon/texio.praat names.
#include "fapcast/corpus/textgrid.hpp"
#include "fapcast/core/input_error.hpp"
#include "support/bad_inputs.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

const std::filesystem::path kTg = std::filesystem::path(FAPCAST_TEST_DATA) / "alignment/textgrid";

Alignment read_file(const std::filesystem::path& p) { return read_textgrid(test::slurp(p), p.filename().string()); }

TEST(TextGridForms, BinaryGridsEqualTheirTextOriginals) {
  const auto speech = std::filesystem::path(FAPCAST_TEST_DATA) / "speech";
  EXPECT_EQ(read_file(kTg / "praat-binary/msajc003.binary.TextGrid"), read_file(speech / "emu-ae/msajc003.TextGrid"));
  EXPECT_EQ(read_file(kTg / "praat-binary/bobby_phones.binary.TextGrid"), read_file(speech / "praatio/bobby_phones.TextGrid"));
  const Alignment nws = read_file(kTg / "praat-binary/the_north_wind_and_the_sun.binary.TextGrid");
  ASSERT_EQ(nws.tiers.size(), 2u);
  EXPECT_EQ(nws.tiers[0].intervals.at(1).label, "ð");  // a UTF-16 string in the binary form
  EXPECT_EQ(nws.tiers[1].kind, TierKind::points);
}

TEST(TextGridForms, ChronologicalGridsFromWebMausAndPraat) {
  const Alignment ktn = read_file(kTg / "maus/ktn_arctic_a0009.TextGrid");
  ASSERT_EQ(ktn.tiers.size(), 1u);
  EXPECT_EQ(ktn.tiers[0].name, "MAU");
  EXPECT_EQ(ktn.tiers[0].intervals.size(), 40u);
  EXPECT_EQ(ktn.tiers[0].intervals.at(4).label, "3`");
  const Alignment sine = read_file(kTg / "praat-texio/sineWithNoise.TextGrid");
  ASSERT_EQ(sine.tiers.size(), 3u);
  EXPECT_EQ(sine.tiers[2].kind, TierKind::points);
}

TEST(TextGridForms, PraatsTexioVerdicts) {
  EXPECT_NO_THROW(read_file(kTg / "praat-texio/texio1.TextGrid"));
  // file -> the line Praat's error names (test/fon/texio.praat)
  const std::pair<int, int> refused[] = {{2, 10}, {3, 13}, {4, 6}, {5, 18}, {6, 17}, {7, 21}, {8, 6}, {9, 14},
                                         {10, 18}, {11, 18}, {12, 6}, {13, 14}, {14, 14}, {15, 18}, {16, 18},
                                         {17, 6}, {18, 6}, {19, 6}, {20, 6}};
  for (const auto& [n, line] : refused) {
    const auto name = "texio" + std::to_string(n) + ".TextGrid";
    SCOPED_TRACE(name);
    try {
      (void)read_file(kTg / "praat-texio" / name);
      ADD_FAILURE() << "read";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, static_cast<std::uint64_t>(line)) << e.what();
    }
  }
}

}  // namespace
}  // namespace fapcast
