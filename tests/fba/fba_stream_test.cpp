// Guarantees of the frame-at-a-time FBA coder in both profiles: one access unit per frame
// (spec/fba.md §1, §9).
#include "fapcast/fba/fba_errc.hpp"
#include "fapcast/fba/fba_stream.hpp"
#include "fba_coding_state.hpp"
#include "fba/fba_test_support.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fapcast {
namespace {

using test::kFbaSeed;
using test::reproduce_hint;
using test::test_seed;
using test::encoder_options;

// Encoder and decoder agree on the bit count and the whole coder state after every frame, in
// both profiles; every value within step/2.
TEST(FbaStream, EncoderAndDecoderAgreeOnBitsAndStateAfterEveryFrame) {
  const std::uint64_t seed = test_seed(kFbaSeed);
  SCOPED_TRACE(reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 8; ++trial) {
    const int q = static_cast<int>(rng() % 6);
    auto frames = test::random_track(rng, 200, 1500 / std::max(q, 1) * std::max(q, 1));
    for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
      SCOPED_TRACE(std::string(fba_profile_name(profile)) + " trial " + std::to_string(trial));
      FbaFrameEncoder encoder(encoder_options(profile, q, 1 + static_cast<int>(rng() % 50)), {25, 1});
      FbaFrameDecoder decoder(profile);
      for (std::size_t k = 0; k < frames.size(); ++k) {
        FbaAccessUnit unit;
        ASSERT_FALSE(encoder.encode(frames[k], unit)) << encoder.error_detail();
        FapFrame out;
        ASSERT_FALSE(decoder.decode(unit.bytes, out)) << "frame " << k;
        ASSERT_EQ(decoder.last_bits(), encoder.last_bits()) << "frame " << k;
        ASSERT_LT(decoder.last_bits(), 8 * unit.bytes.size());  // next_start_code() stuffing: 1..8 bits
        ASSERT_GE(decoder.last_bits() + 8, 8 * unit.bytes.size());
        ASSERT_EQ(decoder.coding_state().checksum(), encoder.coding_state().checksum()) << "frame " << k;
        ASSERT_TRUE(decoder.coding_state() == encoder.coding_state()) << "frame " << k;
        ASSERT_EQ(out.mask, frames[k].mask);
        for (int n = 3; n <= kFapCount; ++n)
          ASSERT_LE(2 * std::abs(std::int64_t{out.value(n)} - frames[k].value(n)), fba_step(n, q));
        if (profile == FbaProfile::kFapcast && unit.intra) {
          EXPECT_EQ(decoder.last_frame_number(), static_cast<int>(k));
        } else {
          EXPECT_EQ(decoder.last_frame_number(), -1);
        }
      }
    }
  }
}

TEST(FbaStream, EveryUnitStartsWithThePlaneStartCode) {
  for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    FbaFrameEncoder encoder(encoder_options(profile, 1, 5), {25, 1});
    for (int k = 0; k < 12; ++k) {
      FbaAccessUnit unit;
      ASSERT_FALSE(encoder.encode(FapFrame{}.set(3, 10 * k), unit));
      ASSERT_GE(unit.bytes.size(), 5u);
      EXPECT_EQ(unit.bytes[0], 0);
      EXPECT_EQ(unit.bytes[1], 0);
      EXPECT_EQ(unit.bytes[2], 1);
      EXPECT_EQ(unit.bytes[3], 0xBB);
      EXPECT_EQ(unit.intra, k % 5 == 0) << k;  // the intra period is honoured
    }
  }
}

// A mask change forces an intra frame; in the standard syntax so does a difference beyond the P
// range (the fapcast profile escapes it instead).
TEST(FbaStream, IntraForcedOnMaskChangeAndOnRangeExit) {
  for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    FbaFrameEncoder encoder(encoder_options(profile, 1, 1000), {25, 1});
    FbaAccessUnit unit;
    ASSERT_FALSE(encoder.encode(FapFrame{}.set(3, 0).set(4, 0), unit));
    EXPECT_TRUE(unit.intra);
    ASSERT_FALSE(encoder.encode(FapFrame{}.set(3, 8).set(4, 0), unit));
    EXPECT_FALSE(unit.intra);
    ASSERT_FALSE(encoder.encode(FapFrame{}.set(3, 8), unit));  // FAP 4 dropped from the mask
    EXPECT_TRUE(unit.intra);
    ASSERT_FALSE(encoder.encode(FapFrame{}.set(3, 12), unit));
    EXPECT_FALSE(unit.intra);
    // open_jaw's default P range is 360 levels of 4 units: a jump of 2000 units leaves it.
    ASSERT_FALSE(encoder.encode(FapFrame{}.set(3, 2012), unit));
    EXPECT_EQ(unit.intra, profile == FbaProfile::kStandard);
    ASSERT_FALSE(encoder.encode(FapFrame{}.set(3, 2016), unit, /*force_intra=*/true));
    EXPECT_TRUE(unit.intra);
  }
}

TEST(FbaStream, PredictedUnitsAreRefusedUntilTheNextIntraUnit) {
  for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    FbaFrameEncoder encoder(encoder_options(profile, 2, 4), {30000, 1001});
    std::vector<FbaAccessUnit> units(9);
    for (std::size_t k = 0; k < units.size(); ++k)
      ASSERT_FALSE(encoder.encode(FapFrame{}.set(5, static_cast<std::int32_t>(3 * k)), units[k]));
    FbaFrameDecoder decoder(profile);
    FapFrame out;
    EXPECT_TRUE(decoder.needs_intra());
    EXPECT_EQ(decoder.decode(units[1].bytes, out), fba_errc::predicted_without_intra);
    ASSERT_FALSE(decoder.decode(units[0].bytes, out));
    EXPECT_EQ(decoder.rate(), (FrameRate{30000, 1001}));
    EXPECT_EQ(decoder.fap_quant(), 2);
    ASSERT_FALSE(decoder.decode(units[1].bytes, out));
    decoder.reset();  // units 2, 3 lost
    EXPECT_TRUE(decoder.needs_intra());
    EXPECT_EQ(decoder.decode(units[3].bytes, out), fba_errc::predicted_without_intra);
    ASSERT_TRUE(units[4].intra);
    ASSERT_FALSE(decoder.decode(units[4].bytes, out));
    EXPECT_EQ(out.value(5), 12);
    ASSERT_FALSE(decoder.decode(units[5].bytes, out));
    EXPECT_EQ(out.value(5), 16);  // step 4: 15 -> 16
  }
}

// A decoder of one profile reads the other's units as garbage or refuses them; reset(profile)
// switches it (what the RTP receiver does on the payload header's F bit).
TEST(FbaStream, ResetSwitchesTheProfile) {
  FbaFrameEncoder fapcast(encoder_options(FbaProfile::kFapcast, 0, 25), {25, 1});
  FbaAccessUnit unit;
  ASSERT_FALSE(fapcast.encode(FapFrame{}.set(3, 100).set(47, 2955), unit));
  FbaFrameDecoder decoder;
  EXPECT_EQ(decoder.profile(), FbaProfile::kStandard);
  FapFrame out;
  decoder.reset(FbaProfile::kFapcast);
  ASSERT_FALSE(decoder.decode(unit.bytes, out));
  EXPECT_EQ(out.value(47), 2955);  // beyond the standard's +/-1860 at fap_quant 0
  EXPECT_EQ(decoder.last_frame_number(), 0);
}

TEST(FbaStream, CallersMistakeIsToldFromABadStream) {
  FbaFrameDecoder decoder;
  FapFrame out;
  const std::error_code empty = decoder.decode({}, out);
  EXPECT_EQ(empty, std::errc::invalid_argument);
  EXPECT_NE(empty.category(), fba_category());
  const std::vector<std::uint8_t> junk{0, 0, 1, 0xB5, 0xFF};
  const std::error_code bad = decoder.decode(junk, out);
  EXPECT_EQ(bad, fba_errc::bad_start_code);
  EXPECT_EQ(bad.category(), fba_category());
  FbaFrameEncoder encoder(encoder_options(FbaProfile::kStandard, 40, 25), {25, 1});
  FbaAccessUnit unit;
  EXPECT_EQ(encoder.encode(FapFrame{}, unit), std::errc::invalid_argument);
  FbaFrameEncoder odd_rate(encoder_options(FbaProfile::kStandard, 1, 25), {1000, 3});
  EXPECT_EQ(odd_rate.encode(FapFrame{}, unit), fba_errc::uncodable_frame_rate);
}

// Reading past the end gives zeros and a sticky error, never a read out of bounds; a unit whose
// stuffing is not next_start_code()'s is refused.
TEST(FbaStream, EveryTruncationIsRefused) {
  for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    FbaFrameEncoder encoder(encoder_options(profile, 1, 25), {25, 1});
    FbaAccessUnit unit;
    FapFrame frame;
    for (int n = 3; n <= 40; ++n) frame.set(n, n * 7 - 150);
    frame.mask.set(1);
    frame.viseme = {3, 7, 40, true};
    ASSERT_FALSE(encoder.encode(frame, unit));
    for (std::size_t cut = 1; cut < unit.bytes.size(); ++cut) {
      FbaFrameDecoder decoder(profile);
      FapFrame out;
      const std::error_code e = decoder.decode(std::span(unit.bytes).first(cut), out);
      EXPECT_TRUE(e) << "cut at " << cut;
      EXPECT_EQ(e.category(), fba_category());
      EXPECT_TRUE(decoder.needs_intra());
    }
    auto longer = unit.bytes;
    longer.push_back(0xFF);
    FbaFrameDecoder decoder(profile);
    FapFrame out;
    EXPECT_TRUE(decoder.decode(longer, out));
  }
}

TEST(FbaStream, FrameRateFieldsRoundTrip) {
  for (const FrameRate r : {FrameRate{25, 1}, FrameRate{30000, 1001}, FrameRate{24000, 1001}, FrameRate{25, 2},
                            FrameRate{60, 1}, FrameRate{255, 1}, FrameRate{1, 16}, FrameRate{4095, 16}}) {
    const auto fields = fba_rate_fields(r);
    ASSERT_TRUE(fields) << r;
    EXPECT_EQ(fields->rate(), r);
  }
  // frame_rate + seconds / 16: 25 is 25 + 0/16, 12.5 is 12 + 8/16.
  EXPECT_EQ(fba_rate_fields({25, 1}), (FbaRateFields{25, 0, false}));
  EXPECT_EQ(fba_rate_fields({25, 2}), (FbaRateFields{12, 8, false}));
  EXPECT_EQ(fba_rate_fields({30000, 1001}), (FbaRateFields{30, 0, true}));
  EXPECT_FALSE(fba_rate_fields({1000, 3}));
  EXPECT_FALSE(fba_rate_fields({256, 1}));
  EXPECT_FALSE(fba_rate_fields({1, 15}));
}

TEST(FbaStream, QuantiserFollowsTheRule) {
  EXPECT_EQ(fba_quantise(2, 4), 0);   // |v| <= step/2 -> 0
  EXPECT_EQ(fba_quantise(3, 4), 1);   // (3 + 2) / 4
  EXPECT_EQ(fba_quantise(-6, 4), -2);
  EXPECT_EQ(fba_quantise(1860, 1), 1860);
  EXPECT_EQ(fba_step(3, 0), 1);       // lossless
  EXPECT_EQ(fba_step(3, 2), 8);       // open_jaw QP 4
  EXPECT_EQ(fba_range_levels(31, 0), 1860);
  EXPECT_EQ(fba_range_levels(31, 8), 232);
  EXPECT_EQ(fba_range_field(61, 1), 2);
  // The defaults: the FAP table's range rounded up to whole fields (raise_nose: 680 -> 720).
  EXPECT_EQ(fba_default_range_levels(63, 1), (FbaRangeLevels{-720, 720, -180, 180}));
  EXPECT_EQ(fba_default_range_levels(3, 4), (FbaRangeLevels{-270, 270, -90, 90}));
  // Viseme blend and expression intensities: 63 quantised by fap_quant.
  EXPECT_EQ(fba_blend_levels(0), 63);
  EXPECT_EQ(fba_blend_levels(1), 63);
  EXPECT_EQ(fba_blend_levels(2), 32);  // 32 x 2 = 64
  EXPECT_EQ(fba_blend_levels(5), 13);  // 13 x 5 = 65
}

}  // namespace
}  // namespace fapcast
