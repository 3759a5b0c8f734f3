// fap_stats: one pass over the frames agrees with a direct per-FAP scan, on hand-made and
// random sequences.
#include "fapcast/codec/fap_stats.hpp"

#include "support/fap_sequences.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace fapcast {
namespace {

TEST(FapStats, HandMadeSequence) {
  FapSequence s;
  s.rate = {30000, 1001};
  FapFrame a;
  a.set(3, -6).set(48, 1200);
  a.mask.set(1);
  a.viseme = {4, 9, 63, false};  // blend 63: select2 does not contribute
  FapFrame b;
  b.set(3, 315);
  b.mask.set(2);
  b.expression = {1, 40, 6, 10, false, false};
  s.frames = {a, b, b};
  const FapStats st = fap_stats(s);
  EXPECT_EQ(st.frame_count, 3u);
  EXPECT_EQ(st.duration_ms, 100);  // 3 frames at 29.97 fps = 100.1 ms
  ASSERT_EQ(st.masked_faps.size(), 4u);
  EXPECT_EQ(st.masked_faps[0], (FapValueRange{1, 1, 4, 4}));
  EXPECT_EQ(st.masked_faps[1], (FapValueRange{2, 2, 1, 1}));
  EXPECT_EQ(st.masked_faps[2], (FapValueRange{3, 3, -6, 315}));
  EXPECT_EQ(st.masked_faps[3], (FapValueRange{48, 1, 1200, 1200}));
  EXPECT_EQ(st.visemes_used.to_string(), "000000000010000");
  EXPECT_EQ(st.expressions_used.to_string(), "1000010");
}

TEST(FapStats, EmptySequence) {
  const FapStats st = fap_stats(FapSequence{});
  EXPECT_EQ(st.frame_count, 0u);
  EXPECT_EQ(st.duration_ms, 0);
  EXPECT_TRUE(st.masked_faps.empty());
}

TEST(FapStats, AgreesWithADirectScanOnRandomSequences) {
  const std::uint64_t seed = test::test_seed(test::kFapSequenceSeed);
  SCOPED_TRACE("reproduce with FAPCAST_SEED=" + std::to_string(seed));
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 20; ++trial) {
    const FapSequence s = test::random_fap_sequence(rng, 40);
    const FapStats st = fap_stats(s);
    EXPECT_EQ(st.duration_ms, frame_to_sample(40, s.rate, SampleRate{1000}));
    std::size_t i = 0;
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
      std::vector<std::int32_t> seen;
      for (const auto& f : s.frames)
        if (f.mask.test(n)) seen.push_back(f.value(n));
      while (i < st.masked_faps.size() && st.masked_faps[i].fap < n) ++i;
      if (seen.empty()) {
        EXPECT_TRUE(i == st.masked_faps.size() || st.masked_faps[i].fap != n);
        continue;
      }
      ASSERT_LT(i, st.masked_faps.size());
      const auto [lo, hi] = std::minmax_element(seen.begin(), seen.end());
      EXPECT_EQ(st.masked_faps[i], (FapValueRange{n, seen.size(), *lo, *hi}));
    }
  }
}

}  // namespace
}  // namespace fapcast
