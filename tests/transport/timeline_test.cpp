#include "fapcast/transport/timeline.hpp"
#include "fapcast/transport/track_resample.hpp"

#include "fapcast/core/frame_rate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace fapcast {
namespace {


// A track whose frame k carries k in open_jaw (FAP 3), so every output names its source.
FapSequence numbered_track(FrameRate rate, std::int64_t n) {
  FapSequence seq;
  seq.name = "numbered";
  seq.rate = rate;
  seq.frames.resize(static_cast<std::size_t>(n));
  for (std::int64_t k = 0; k < n; ++k) seq.frames[static_cast<std::size_t>(k)].set(3, static_cast<std::int32_t>(k));
  return seq;
}

TEST(Timeline, FramesCarryTheirFirstSample) {
  const auto timed = place_on_timeline(numbered_track({30000, 1001}, 5), SampleRate{48000});
  ASSERT_EQ(timed.size(), 5u);
  EXPECT_EQ(timed[0].sample, 0);
  EXPECT_EQ(timed[1].sample, 1602);  // 48000 * 1001 / 30000 = 1601.6
  EXPECT_EQ(timed[4].sample, 6406);  // 6406.4
  for (const auto& t : timed)
    EXPECT_EQ(sample_to_frame(t.sample, {30000, 1001}, SampleRate{48000}), t.frame.value(3));
}

// Frame by frame, the resampler gives resample_track's frames to the bit, in both modes, at
// rates up and down and between rates with no common grid.
TEST(TrackResampler, IsResampleTrackFrameByFrame) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int32_t> value(-2000, 2000);
  for (const auto& [from, to] : std::vector<std::pair<FrameRate, FrameRate>>{
           {{60, 1}, {25, 1}}, {{60, 1}, {30000, 1001}}, {{60, 1}, {60, 1}}, {{60, 1}, {120, 1}}, {{25, 1}, {7, 1}}}) {
    for (const std::int64_t n : {0, 1, 2, 13, 600}) {
      FapSequence seq = numbered_track(from, n);
      for (FapFrame& f : seq.frames) {
        f.set(48, value(rng));
        if (value(rng) > 0) f.set(19, value(rng));  // masked in some frames only: held, not interpolated
      }
      for (const ResampleMode mode : {ResampleMode::kHold, ResampleMode::kLinear}) {
        std::vector<FapFrame> got;
        TrackResampler resampler(from, to, mode, [&](std::int64_t j, const FapFrame& f) {
          EXPECT_EQ(j, static_cast<std::int64_t>(got.size()));
          got.push_back(f);
        });
        for (const FapFrame& f : seq.frames) resampler.push(f);
        resampler.finish();
        EXPECT_EQ(got, resample_track(seq, to, mode).frames) << from.fps() << " -> " << to.fps() << ", " << n << " frames";
        EXPECT_THROW(resampler.push(FapFrame{}), std::logic_error);
      }
    }
  }
}

TEST(Timeline, DurationSampleConversionIsExactOverDays) {
  const std::int64_t two_days = 2 * 86400ll * 192000;
  EXPECT_EQ(samples_to_duration(two_days, SampleRate{192000}), std::chrono::hours(48));
  EXPECT_EQ(duration_to_samples(std::chrono::hours(48), SampleRate{192000}), two_days);
  EXPECT_EQ(samples_to_duration(1, SampleRate{48000}), std::chrono::nanoseconds(20833));
}

struct RateCase {
  FrameRate from;
  FrameRate to;
};
class HourLongResample : public testing::TestWithParam<RateCase> {};

// Over an hour of frames, hold mode shows at output time j / to the source frame k whose
// interval [k / from, (k + 1) / from) contains it: checked for every output frame with exact
// cross-multiplication, so any drift would fail at the frame it appears.
TEST_P(HourLongResample, HoldShowsTheFrameOnScreenWithoutDrift) {
  const auto [from, to] = GetParam();
  const std::int64_t n = static_cast<std::int64_t>(3600.0 * from.fps());
  const FapSequence out = resample_track(numbered_track(from, n), to, ResampleMode::kHold);
  EXPECT_EQ(out.rate, to);
  const auto count = static_cast<std::int64_t>(out.frames.size());
  EXPECT_EQ(count, resampled_frame_count(n, from, to));
  // The output covers the input's duration and no more: (count - 1) / to < n / from <= count / to.
  __extension__ typedef __int128 W;
  EXPECT_LT(W(count - 1) * to.denominator * from.numerator, W(n) * from.denominator * to.numerator);
  EXPECT_LE(W(n) * from.denominator * to.numerator, W(count) * to.denominator * from.numerator);
  for (std::int64_t j = 0; j < count; ++j) {
    const std::int64_t k = out.frames[static_cast<std::size_t>(j)].value(3);
    // k / from <= j / to < (k + 1) / from
    const W lhs = W(k) * from.denominator * to.numerator;
    const W t = W(j) * to.denominator * from.numerator;
    const W rhs = W(k + 1) * from.denominator * to.numerator;
    ASSERT_TRUE(lhs <= t && t < rhs) << "output frame " << j << " shows source frame " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Table, HourLongResample,
                         testing::Values(RateCase{{60, 1}, {25, 1}}, RateCase{{25, 1}, {60, 1}},
                                         RateCase{{30000, 1001}, {30, 1}},
                                         RateCase{{30, 1}, {30000, 1001}},
                                         RateCase{{24000, 1001}, {50, 1}},
                                         RateCase{{60, 1}, {60, 1}}));

TEST(Resample, SameRateIsIdentity) {
  const FapSequence seq = numbered_track({25, 1}, 100);
  EXPECT_EQ(resample_track(seq, {50, 2}, ResampleMode::kLinear).frames, seq.frames);
}

TEST(Resample, LinearInterpolatesAtTheExactFraction) {
  FapSequence seq = numbered_track({25, 1}, 3);
  seq.frames[0].set(4, -10);
  seq.frames[1].set(4, 10);
  seq.frames[2].set(4, 11);
  seq.frames[1].viseme = {3, 4, 20, false};
  seq.frames[1].mask.set(1);
  const FapSequence out = resample_track(seq, {100, 1}, ResampleMode::kLinear);
  ASSERT_EQ(out.frames.size(), 12u);
  EXPECT_EQ(out.frames[1].value(4), -5);   // a quarter of the way: -10 + 20/4
  EXPECT_EQ(out.frames[2].value(4), 0);
  EXPECT_EQ(out.frames[3].value(4), 5);
  EXPECT_EQ(out.frames[4].value(4), 10);
  EXPECT_EQ(out.frames[6].value(4), 11);   // 10.5 rounds away from zero
  EXPECT_EQ(out.frames[11].value(4), 11);  // past the last frame: held
  EXPECT_FALSE(out.frames[3].mask.test(1));  // FAP 1 is held from the earlier frame, not blended
  EXPECT_TRUE(out.frames[5].mask.test(1));
  EXPECT_EQ(out.frames[5].viseme, seq.frames[1].viseme);
}

TEST(Resample, LinearAgreesWithHoldOnFramesThatLandExactly) {
  const FapSequence seq = numbered_track({60, 1}, 600);
  const FapSequence hold = resample_track(seq, {30, 1}, ResampleMode::kHold);
  const FapSequence lin = resample_track(seq, {30, 1}, ResampleMode::kLinear);
  EXPECT_EQ(hold.frames, lin.frames);  // 30 divides 60: every output lands on a source frame
  const FapSequence up = resample_track(seq, {120, 1}, ResampleMode::kLinear);
  for (std::size_t j = 0; j + 2 < up.frames.size(); j += 2) EXPECT_EQ(up.frames[j], seq.frames[j / 2]);
}

// The interpolation is exact rational rounding on every path (the denominator decides: doubles up
// to 2^20, 64-bit integers up to 2^30, 128-bit beyond), over the whole int32 range.
TEST(Resample, LinearRoundsExactlyAtEveryDenominator) {
  __extension__ typedef __int128 Int128;
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<std::int32_t> any(std::numeric_limits<std::int32_t>::min(),
                                                  std::numeric_limits<std::int32_t>::max());
  std::uniform_int_distribution<std::int32_t> small(-2000, 2000);
  FapSequence seq = numbered_track({60, 1}, 240);
  for (std::size_t k = 0; k < seq.frames.size(); ++k) {
    seq.frames[k].set(4, any(rng));
    seq.frames[k].set(5, small(rng));
    seq.frames[k].set(6, k % 2 ? std::numeric_limits<std::int32_t>::max() : std::numeric_limits<std::int32_t>::min());
  }
  // 60 fps spelled with denominators 1, 2,000,003 and 50,000,000, shown at 25 and 29.97 fps.
  for (const FrameRate from : {FrameRate{60, 1}, FrameRate{120000180, 2000003}, FrameRate{3000000000u, 50000000}})
    for (const FrameRate to : {FrameRate{25, 1}, FrameRate{30000, 1001}}) {
      seq.rate = from;
      const FapSequence out = resample_track(seq, to, ResampleMode::kLinear);
      for (std::size_t j = 0; j < out.frames.size(); ++j) {
        const SourcePosition p = source_position(static_cast<std::int64_t>(j), from, to);
        const auto k = std::min(static_cast<std::size_t>(p.index), seq.frames.size() - 1);
        for (int fap = 3; fap <= 6; ++fap) {
          const std::int32_t a = seq.frames[k].value(fap);
          std::int32_t want = a;
          if (p.remainder != 0 && k + 1 < seq.frames.size()) {
            // round(s / den) half away from zero = floor((2|s| + den) / (2 den)) with s's sign.
            const Int128 s = Int128{a} * p.denominator + (Int128{seq.frames[k + 1].value(fap)} - a) * p.remainder;
            const Int128 magnitude = (2 * (s < 0 ? -s : s) + p.denominator) / (2 * Int128{p.denominator});
            want = static_cast<std::int32_t>(s < 0 ? -magnitude : magnitude);
          }
          ASSERT_EQ(out.frames[j].value(fap), want) << "frame " << j << " FAP " << fap << " from " << from.numerator
                                                    << "/" << from.denominator << " to " << to.numerator << "/" << to.denominator;
        }
      }
    }
}

TEST(Resample, EmptyStaysEmpty) {
  EXPECT_TRUE(resample_track(numbered_track({25, 1}, 0), {60, 1}, ResampleMode::kHold).frames.empty());
}

}  // namespace
}  // namespace fapcast
