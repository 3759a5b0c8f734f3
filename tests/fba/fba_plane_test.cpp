// White-box guarantees of the plane coder (fba/src): the standard's ranges in force, and the
// check that keeps a plane only when every standard decoder reads it alike (spec/fba.md §2, §4).
#include "fapcast/fba/fba_file.hpp"
#include "fba_plane.hpp"
#include "fba/fba_test_support.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fapcast {
namespace {

using test::kFbaSeed;
using test::reproduce_hint;
using test::test_seed;

// Ranges persist from intra plane to intra plane; the defaults are set at the first, at its
// fap_quant, and again whenever FAP 4's I range is 0..0 (the published decoder's rule); viseme
// blend and intensity ranges follow fap_quant except at 0, where they stay as they were.
TEST(FbaPlane, RangesInForceFollowThePublishedDecoder) {
  FbaCodingState s;
  FapMask mask;
  mask.set(3).set(4).set(63);
  std::array<FbaRangeFields, kFapCount> fields{};
  s.begin_standard_intra(2, mask, {}, fields);
  EXPECT_EQ(s.ranges[62], (FbaRangeLevels{-360, 360, -90, 90}));  // raise_nose 680 -> 720, / 2
  EXPECT_EQ(s.blend_levels, 32);
  fields[2].p_max = 3;  // FAP 3: P max 60 * 3 / 4 = 45 levels at fap_quant 4; FAP 63's field 0
  s.begin_standard_intra(4, mask, {.p_max = true}, fields);
  EXPECT_EQ(s.ranges[62], (FbaRangeLevels{-360, 360, -90, 0}));  // the rest kept as it was, not re-scaled
  EXPECT_EQ(s.ranges[2].p_max, 45);
  EXPECT_EQ(s.blend_levels, 16);
  s.begin_standard_intra(0, mask, {}, fields);
  EXPECT_EQ(s.blend_levels, 16);  // kept at fap_quant 0
  EXPECT_EQ(s.ranges[2].p_max, 45);
  fields[3] = {0, 0, 1, 1};  // FAP 4's I range 0..0
  s.begin_standard_intra(1, mask, {.i_max = true, .i_min = true}, fields);
  EXPECT_EQ(s.ranges[3].i_max, 0);
  s.begin_standard_intra(1, mask, {}, fields);  // so the next intra plane starts from the defaults
  EXPECT_EQ(s.ranges[3], fba_default_range_levels(4, 1));
  EXPECT_EQ(s.ranges[2], fba_default_range_levels(3, 1));
}

// reads_alike: 22 zeros across a segment's end that the reference reading does not stuff (it
// counts within segments only), a continuous reader would; and zeros at a segment's end that
// run on into the next bits make the published decoder's look-ahead take a bit for a stuffed one.
TEST(FbaPlane, ReadsAlikeFindsWhereDecodersWouldDisagree) {
  {
    FbaBitWriter w;
    const auto mark = w.mark();
    w.put_bit(1);
    w.begin_segment();
    w.put(0b10, 2);
    w.put(0, 12);  // 12 zeros end the segment (as a flush can)
    w.end_segment();
    w.put(0, 10);  // then raw zeros: 22 in a row, unstuffed
    w.put_bit(1);
    EXPECT_FALSE(detail::reads_alike(w, mark, 0, true));
  }
  {
    FbaBitWriter w;
    const auto mark = w.mark();
    w.begin_segment();
    w.put(0, 19);  // 19 zeros: every reader reads them as they are ...
    w.put_bit(1);
    w.end_segment();
    EXPECT_TRUE(detail::reads_alike(w, mark, 0, true));
    EXPECT_EQ(detail::continuous_zero_run(w, mark, 0), 0);
    // ... unless a continuous reader counted 4 zeros before the plane (the previous one's end).
    EXPECT_FALSE(detail::reads_alike(w, mark, 4, true));
  }
  {
    FbaBitWriter w;
    const auto mark = w.mark();
    w.put_bit(1);
    w.begin_segment();
    w.put(0b1, 1);
    w.put(0, 9);
    w.end_segment();
    for (int i = 0; i < 20; ++i) w.put_bit(i == 19);  // 19 more zeros (no stuffing: raw bits)
    // A continuous reader stuffs after 22, the reference one not: they disagree; the published
    // decoder's 14-bit look-ahead counts 9 + 13 = 22 zeros and takes the next bit as stuffing.
    EXPECT_FALSE(detail::reads_alike(w, mark, 0, true));
  }
}

// On zero-rich random tracks the standard encoder meets planes it must code otherwise; what it
// writes then reads alike under both stuffing readings and the published decoder's give-back.
TEST(FbaPlane, TheEncoderRecodesWhatDecodersWouldReadOtherwise) {
  const std::uint64_t seed = test_seed(kFbaSeed);
  SCOPED_TRACE(reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  std::uint64_t recoded = 0;
  for (int trial = 0; trial < 400 && recoded < 3; ++trial) {
    std::vector<FapFrame> frames = test::random_track(rng, 60, 1800);
    for (FapFrame& f : frames)  // values at the range's ends: symbols at an interval's bottom
      for (int n = 3; n <= kFapCount; ++n)
        if (f.mask.test(n) && rng() % 3 == 0) f.set(n, rng() % 2 ? 1860 : -1860);
    const FapSequence seq{"", {25, 1}, frames};
    FbaEncoderOptions o;
    o.fap_quant = 0;
    o.intra_period = 1 + static_cast<int>(rng() % 20);
    FbaEncodeStats stats;
    const auto bytes = encode_fba(seq, o, &stats);
    if (stats.recoded_for_decoders == 0) continue;
    recoded += stats.recoded_for_decoders;
    SCOPED_TRACE("trial " + std::to_string(trial));
    const auto reference = decode_fba(bytes);
    ASSERT_TRUE(reference.report.ok());
    EXPECT_EQ(reference.sequence, seq);
    if (stats.not_read_alike > 0) continue;
    FbaDecodeOptions continuous, fixed;
    continuous.stuffing = FbaStuffing::kContinuous;
    fixed.fixed_give_back = true;
    for (const FbaDecodeOptions& other : {continuous, fixed}) {
      const auto r = decode_fba(bytes, other);
      ASSERT_TRUE(r.report.ok()) << r.report.errors.front().message();
      EXPECT_EQ(r.sequence, seq);
    }
  }
  EXPECT_GT(recoded, 0u) << "no plane needed another coding: the check was never exercised";
}

}  // namespace
}  // namespace fapcast
