// Where a long recording is cut for alignment piece by piece (recognise/src/pauses.hpp, private:
// spec/recognise.md, "Long recordings").
#include "pauses.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace fapcast {
namespace {

constexpr std::int64_t kRate = 16000;

// Tone bursts with quiet gaps between them (a faint hiss in the gaps, 50 dB down).
struct Signal {
  std::vector<std::int16_t> samples;
  std::vector<Pause> gaps;  // where the gaps are, samples
  void tone(double seconds) {
    const auto n = static_cast<std::int64_t>(seconds * kRate);
    for (std::int64_t i = 0; i < n; ++i)
      samples.push_back(static_cast<std::int16_t>(8000 * std::sin(2 * std::numbers::pi * 220.0 * static_cast<double>(i) / kRate)));
  }
  void gap(double seconds) {
    const auto n = static_cast<std::int64_t>(seconds * kRate);
    const auto start = static_cast<std::int64_t>(samples.size());
    for (std::int64_t i = 0; i < n; ++i) samples.push_back(static_cast<std::int16_t>(i % 7 == 0 ? 25 : -4));
    gaps.push_back({start, start + n});
  }
};

TEST(Pauses, GapsOfAQuarterSecondOrMoreAreFoundShorterOnesAreNot) {
  Signal s;
  s.tone(1.0);
  s.gap(0.4);
  s.tone(1.0);
  s.gap(0.1);  // a stop closure, not a pause
  s.tone(1.0);
  s.gap(0.3);
  s.tone(0.5);
  const std::vector<Pause> p = find_pauses(s.samples);
  ASSERT_EQ(p.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const Pause& gap = s.gaps[i == 0 ? 0 : 2];
    EXPECT_NEAR(static_cast<double>(p[i].start), static_cast<double>(gap.start), 160.0) << i;
    EXPECT_NEAR(static_cast<double>(p[i].end), static_cast<double>(gap.end), 160.0) << i;
  }
}

TEST(Pauses, ASteadySignalHasNone) {
  Signal s;
  s.tone(5.0);
  EXPECT_TRUE(find_pauses(s.samples).empty());
  EXPECT_TRUE(find_pauses(std::vector<std::int16_t>(kRate * 5, 0)).empty());  // digital silence: no contrast
}

TEST(Pauses, CutsFallInTheLongestPauseOfEachWindowAndLeaveNoShortPieceBehind) {
  // a pause every 2 s (0.3 s long), the one at 7.x s and at 15.x s longer (0.6 s)
  Signal s;
  for (int k = 0; k < 10; ++k) {
    s.tone(1.7);
    s.gap(k == 3 || k == 7 ? 0.6 : 0.3);
  }
  s.tone(1.0);
  const std::vector<Pause> p = find_pauses(s.samples);
  ASSERT_EQ(p.size(), 10u);
  const auto length = static_cast<std::int64_t>(s.samples.size());
  const std::vector<std::int64_t> cuts = cut_points(p, length, 5 * kRate, 9 * kRate);
  ASSERT_EQ(cuts.size(), 2u);
  EXPECT_GE(cuts[0], s.gaps[3].start);
  EXPECT_LT(cuts[0], s.gaps[3].end);
  EXPECT_GE(cuts[1], s.gaps[7].start);
  EXPECT_LT(cuts[1], s.gaps[7].end);
  // the rest after the second cut (5.3 s) is over half a piece: kept as the last piece. A cut
  // that would leave less than half a piece behind (5.3 s of 14) is not made.
  EXPECT_TRUE(cut_points(p, length, 14 * kRate, 20 * kRate).empty());
  EXPECT_TRUE(cut_points({}, length, 5 * kRate, 9 * kRate).empty());
}

}  // namespace
}  // namespace fapcast
