// Guarantees of the whole-file FBA coder in both profiles (spec/fba.md), each a test.
#include "fapcast/fba/fba_errc.hpp"
#include "fapcast/fba/fba_file.hpp"
#include "fapcast/fba/fba_stream.hpp"
#include "fba_coding_state.hpp"
#include "fba/fba_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace fapcast {
namespace {

using test::kFbaSeed;
using test::reproduce_hint;
using test::test_seed;
using test::run_offsets;
using test::encoder_options;

FapMask lip_jaw_tongue_mask() {
  FapMask m;
  for (int g : {2, 6, 8}) {
    const FapRange r = fap_group(g);
    for (int n = r.first; n <= r.last; ++n) m.set(n);
  }
  return m;
}

FapSequence sequence_of(std::vector<FapFrame> frames, FrameRate rate = {25, 1}) {
  return FapSequence{"", rate, std::move(frames)};
}

// Every value within step/2 of the input, masks and FAP 1/2 fields as sent (FAP 1/2 exactly at
// fap_quant 0 and 1, on their grid of fap_quant otherwise).
void expect_within_half_a_step(const FapSequence& in, const FapSequence& out, int q) {
  ASSERT_EQ(out.frames.size(), in.frames.size());
  for (std::size_t k = 0; k < in.frames.size(); ++k) {
    const FapFrame& a = in.frames[k];
    const FapFrame& b = out.frames[k];
    ASSERT_EQ(b.mask, a.mask) << "frame " << k;
    const int step = std::max(q, 1);
    if (a.mask.test(1)) {
      ASSERT_EQ(b.viseme.select1, a.viseme.select1);
      ASSERT_EQ(b.viseme.select2, a.viseme.select2);
      ASSERT_EQ(b.viseme.def, a.viseme.def);
      ASSERT_LE(2 * std::abs(b.viseme.blend - a.viseme.blend), step) << "frame " << k;
    }
    if (a.mask.test(2)) {
      ASSERT_EQ(b.expression.select1, a.expression.select1);
      ASSERT_EQ(b.expression.select2, a.expression.select2);
      ASSERT_LE(2 * std::abs(b.expression.intensity1 - a.expression.intensity1), step);
      ASSERT_LE(2 * std::abs(b.expression.intensity2 - a.expression.intensity2), step);
    }
    for (int n = 3; n <= kFapCount; ++n)
      ASSERT_LE(2 * std::abs(std::int64_t{b.value(n)} - a.value(n)), fba_step(n, q)) << "frame " << k << " FAP " << n;
  }
}

// What the encoder wrote is read alike by both stuffing readings and by the published decoder's
// fixed give-back (standard), with the encoder's final coder state.
FbaDecodeResult decode_alike(const std::vector<std::uint8_t>& bytes, const FbaEncodeStats& stats, FbaProfile profile) {
  const FbaDecodeResult r = decode_fba(bytes);
  EXPECT_TRUE(r.report.ok()) << (r.report.errors.empty() ? "" : r.report.errors.front().message());
  EXPECT_EQ(r.report.profile, profile);
  EXPECT_EQ(r.report.state_checksum, stats.state_checksum);
  if (profile == FbaProfile::kStandard && stats.not_read_alike == 0) {
    FbaDecodeOptions continuous, fixed;
    continuous.stuffing = FbaStuffing::kContinuous;
    fixed.stuffing = FbaStuffing::kReference;
    fixed.fixed_give_back = true;
    for (const FbaDecodeOptions& o : {continuous, fixed}) {
      const FbaDecodeResult other = decode_fba(bytes, o);
      EXPECT_TRUE(other.report.ok()) << (other.report.errors.empty() ? "" : other.report.errors.front().message());
      EXPECT_EQ(other.sequence, r.sequence);
      EXPECT_EQ(other.report.state_checksum, stats.state_checksum);
    }
  }
  return r;
}

// Random sequences of every shape round-trip within step/2 in both profiles: random masks (FAP 1
// and 2 included), rates, quantisers, intra periods, mask changes; both sides end in the same
// coder state; the standard streams read alike under every reading.
TEST(FbaFile, RandomRoundTripsInBothProfiles) {
  const std::uint64_t seed = test_seed(kFbaSeed);
  SCOPED_TRACE(reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  std::uint64_t recoded = 0;
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const int q = static_cast<int>(rng() % 9);
    auto frames = test::random_track(rng, 1 + rng() % 120, 1 + static_cast<int>(rng() % 1800) / std::max(q, 1) * std::max(q, 1));
    for (auto& f : frames) {
      if (rng() % 50 == 0) f.mask.set(3 + static_cast<int>(rng() % 66), false);  // a mask change
      for (int n = 3; n <= kFapCount; ++n)
        if (!f.mask.test(n)) f.values[static_cast<std::size_t>(n - 1)] = 0;
    }
    const FapSequence seq = sequence_of(frames, rng() % 2 ? FrameRate{25, 1} : FrameRate{30000, 1001});
    for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
      SCOPED_TRACE(fba_profile_name(profile));
      FbaEncodeStats stats;
      const auto bytes = encode_fba(seq, encoder_options(profile, q, 1 + static_cast<int>(rng() % 30)), &stats);
      const FbaDecodeResult result = decode_alike(bytes, stats, profile);
      EXPECT_EQ(result.sequence.rate, seq.rate);
      expect_within_half_a_step(seq, result.sequence, q);
      recoded += stats.recoded_for_decoders;
    }
  }
  RecordProperty("recoded_for_decoders", static_cast<int>(recoded));
}

// At fap_quant 0 every value inside +/-1860 comes back exactly in the standard syntax, and every
// int32 value (FAP 47 and head rotations far beyond 1860 included) in the fapcast profile.
TEST(FbaFile, LosslessAtQuantZero) {
  const std::uint64_t seed = test_seed(kFbaSeed);
  SCOPED_TRACE(reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> standard(-1860, 1860);
  std::vector<FapFrame> frames(60);
  for (std::size_t k = 0; k < frames.size(); ++k)
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) frames[k].set(n, standard(rng));
  frames[0].set(3, 1860).set(4, -1860);  // both ends of the range
  frames[1].set(3, -1860).set(4, 1860);  // and a P difference of 3720
  const FapSequence seq = sequence_of(frames);
  for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    FbaEncodeStats stats;
    EXPECT_EQ(decode_alike(encode_fba(seq, encoder_options(profile, 0), &stats), stats, profile).sequence, seq);
  }
  std::uniform_int_distribution<std::int32_t> any(std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max());
  std::vector<FapFrame> wide = test::smooth_track(rng, FapMask::all().set(1, false).set(2, false), 80, 40000);
  for (auto& f : wide) f.set(47, 2955).set(48, any(rng) / 1024);  // tongue_roll as `say` makes it; head_pitch
  wide[5].set(49, std::numeric_limits<std::int32_t>::min()).set(50, std::numeric_limits<std::int32_t>::max());
  wide[6].set(49, std::numeric_limits<std::int32_t>::max()).set(50, std::numeric_limits<std::int32_t>::min());
  const FapSequence far = sequence_of(wide);
  FbaEncodeStats stats;
  EXPECT_EQ(decode_alike(encode_fba(far, encoder_options(FbaProfile::kFapcast, 0), &stats), stats, FbaProfile::kFapcast).sequence, far);
  EXPECT_EQ(decode_alike(encode_fba(far, encoder_options(FbaProfile::kFapcast, 0, 7), &stats), stats, FbaProfile::kFapcast).sequence, far);
}

// A value one unit beyond the standard range is refused, naming frame and FAP; never clipped.
TEST(FbaFile, ValueBeyond1860IsRefusedNotClipped) {
  for (const std::int32_t bad : {1861, -1861, 100000}) {
    std::vector<FapFrame> frames(5);
    for (auto& f : frames) f.set(48, 10);
    frames[3].set(48, bad);
    try {
      encode_fba(sequence_of(frames), encoder_options(FbaProfile::kStandard, 0));
      FAIL() << bad << " was accepted";
    } catch (const FbaEncodeError& e) {
      EXPECT_EQ(e.code(), fba_errc::uncodable_value);
      const std::string what = e.what();
      EXPECT_NE(what.find("frame 3"), std::string::npos) << what;
      EXPECT_NE(what.find("FAP 48 head_pitch"), std::string::npos) << what;
      EXPECT_NE(what.find(std::to_string(bad)), std::string::npos) << what;
      EXPECT_NE(what.find("never clipped"), std::string::npos) << what;
    }
    const auto refusal = fba_standard_refusal(sequence_of(frames), 0);
    ASSERT_TRUE(refusal.has_value());
    EXPECT_NE(refusal->find("frame 3, FAP 48 head_pitch"), std::string::npos) << *refusal;
    EXPECT_FALSE(fba_standard_refusal(sequence_of(frames), 1));  // step 170 reaches 316200
    // The fapcast profile codes it.
    EXPECT_EQ(decode_fba(encode_fba(sequence_of(frames), encoder_options(FbaProfile::kFapcast, 0))).sequence, sequence_of(frames));
  }
}

TEST(FbaFile, InvalidOptionsAreTheCallersMistake) {
  const FapSequence seq = sequence_of({FapFrame{}.set(3, 1)});
  for (const FbaEncoderOptions o : {encoder_options(FbaProfile::kStandard, -1), encoder_options(FbaProfile::kStandard, 32),
                                    encoder_options(FbaProfile::kFapcast, 1, -1)}) {
    try {
      encode_fba(seq, o);
      FAIL();
    } catch (const FbaEncodeError& e) {
      EXPECT_EQ(e.code(), std::errc::invalid_argument);
    }
  }
}

struct QuantCase {
  FbaProfile profile;
  int fap_quant;
  std::size_t frames;
};
class FbaQuantised : public ::testing::TestWithParam<QuantCase> {};

// With fap_quant q every decoded value is within step/2 of the input, with no drift.
// (The long runs at two quantisers keep the suite fast under ASan.)
TEST_P(FbaQuantised, WithinHalfAStepWithoutDrift) {
  const int q = GetParam().fap_quant;
  const std::uint64_t seed = test_seed(kFbaSeed) + static_cast<std::uint64_t>(q);
  SCOPED_TRACE(reproduce_hint(seed - static_cast<std::uint64_t>(q)));
  std::mt19937_64 rng(seed);
  FapMask mask;
  mask.set(3).set(5).set(48);  // small mask: the test stays fast under ASan
  const FapSequence seq = sequence_of(test::smooth_track(rng, mask, GetParam().frames, 800));
  const auto result = decode_fba(encode_fba(seq, encoder_options(GetParam().profile, q, 250)));
  ASSERT_TRUE(result.report.ok()) << result.report.errors.front().message();
  expect_within_half_a_step(seq, result.sequence, q);
}

INSTANTIATE_TEST_SUITE_P(Quant, FbaQuantised,
                         ::testing::Values(QuantCase{FbaProfile::kStandard, 1, 100000}, QuantCase{FbaProfile::kStandard, 2, 10000},
                                           QuantCase{FbaProfile::kStandard, 8, 100000}, QuantCase{FbaProfile::kStandard, 31, 10000},
                                           QuantCase{FbaProfile::kFapcast, 1, 30000}, QuantCase{FbaProfile::kFapcast, 4, 10000},
                                           QuantCase{FbaProfile::kFapcast, 31, 10000}));

// The frames of each run: each run decoded alone (the file's opening, the run, the end code).
std::vector<std::size_t> run_first_frames(const std::vector<std::uint8_t>& b) {
  const auto runs = run_offsets(b);
  const std::size_t opening = fba_file_profile(b) == FbaProfile::kFapcast ? fba_fapcast_opening().size() : 4;
  std::vector<std::size_t> out;
  std::size_t frame = 0;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    std::vector<std::uint8_t> one(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(opening));
    if (opening == 4) one.push_back(0x7F);  // next_start_code() after the object start code
    one.insert(one.end(), b.begin() + static_cast<std::ptrdiff_t>(runs[r]),
               b.begin() + static_cast<std::ptrdiff_t>(r + 1 < runs.size() ? runs[r + 1] : b.size() - 4));
    one.insert(one.end(), {0, 0, 1, 0xB1});
    out.push_back(frame);
    frame += decode_fba(one).report.frames_decoded;
  }
  return out;
}

// After corruption the decoder resumes at the next plane start code; a corrupt run is lost whole.
// fapcast profile: the next intra plane's frame_number counts the frames lost exactly, even when
// a run vanished without a trace; standard: the planes met are counted (it has no frame numbers).
TEST(FbaFile, ResynchronisesAfterCorruptionAndCountsLostFrames) {
  std::mt19937_64 rng(test_seed(kFbaSeed));
  const FapSequence seq = sequence_of(test::smooth_track(rng, lip_jaw_tongue_mask(), 100, 300));
  for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    SCOPED_TRACE(fba_profile_name(profile));
    const auto good = encode_fba(seq, encoder_options(profile, 0, 25));
    const auto runs = run_offsets(good);
    ASSERT_EQ(runs.size(), 4u);  // intra planes 0, 25, 50, 75, one run each
    ASSERT_EQ(run_first_frames(good), (std::vector<std::size_t>{0, 25, 50, 75}));
    const auto expect_lost = [&](const FbaDecodeResult& r, std::size_t from, std::size_t to, std::size_t counted) {
      EXPECT_EQ(r.report.frames_lost, counted);
      EXPECT_EQ(r.report.frames_decoded, 100 - (to - from));
      ASSERT_EQ(r.sequence.frames.size(), 100 - (to - from) + counted);
      for (std::size_t k = 0; k < from; ++k) EXPECT_EQ(r.sequence.frames[k], seq.frames[k]) << k;
      for (std::size_t k = from; k < from + counted; ++k) EXPECT_EQ(r.sequence.frames[k], seq.frames[from - 1]) << "held";
      for (std::size_t k = to; k < 100; ++k) EXPECT_EQ(r.sequence.frames[k - (to - from) + counted], seq.frames[k]) << k;
    };
    {
      SCOPED_TRACE("bits flipped in run 2 (frames 50..74)");
      auto bytes = good;
      for (std::size_t i = runs[2] + 40; i < runs[3] - 8; i += 9) bytes[i] ^= 0x5A;
      const auto result = decode_fba(bytes);
      ASSERT_GE(result.report.errors_total, 1u);
      EXPECT_GE(result.report.errors[0].byte_offset, runs[2]);
      expect_lost(result, 50, 75, profile == FbaProfile::kFapcast ? 25 : result.report.frames_lost);
    }
    {
      SCOPED_TRACE("run 1 removed whole");
      auto bytes = good;
      bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(runs[1]), bytes.begin() + static_cast<std::ptrdiff_t>(runs[2]));
      const auto result = decode_fba(bytes);
      if (profile == FbaProfile::kFapcast) {
        ASSERT_EQ(result.report.errors_total, 1u);
        EXPECT_EQ(result.report.errors[0].code, fba_errc::bad_frame_number);
        expect_lost(result, 25, 50, 25);
      } else {
        EXPECT_TRUE(result.report.ok());  // nothing in the standard syntax tells
        expect_lost(result, 25, 50, 0);
      }
    }
  }
}

// The archival preset: an intra plane (a run, a place to enter and resume) every 20 s of frames,
// the guarantees unchanged, and corruption costing that run only.
TEST(FbaFile, ArchivePresetPutsAnIntraPlaneEveryTwentySeconds) {
  EXPECT_EQ(fba_archive_options(FbaProfile::kStandard, 2, {25, 1}).intra_period, 500);
  EXPECT_EQ(fba_archive_options(FbaProfile::kStandard, 2, {30000, 1001}).intra_period, 599);  // rounded down
  EXPECT_EQ(fba_archive_options(FbaProfile::kFapcast, 2, {1, 60}).intra_period, 1);          // one frame a minute
  EXPECT_EQ(fba_archive_options(FbaProfile::kFapcast, 3, {25, 1}).fap_quant, 3);
  EXPECT_EQ(fba_intra_period({}, {25, 1}, true), 250);  // the standard file default: 10 s
  EXPECT_EQ(fba_intra_period(encoder_options(FbaProfile::kFapcast, 0), {25, 1}, true), 500);
  EXPECT_EQ(fba_intra_period({}, {25, 1}, false), 25);  // frame-at-a-time: 1 s
  std::mt19937_64 rng(test_seed(kFbaSeed));
  const FapSequence seq = sequence_of(test::smooth_track(rng, lip_jaw_tongue_mask(), 1200, 600));
  const auto bytes = encode_fba(seq, fba_archive_options(FbaProfile::kStandard, 2, seq.rate));
  ASSERT_EQ(run_first_frames(bytes), (std::vector<std::size_t>{0, 500, 1000}));
  EXPECT_LT(bytes.size(), encode_fba(seq, encoder_options(FbaProfile::kStandard, 2, 25)).size());
  const auto result = decode_fba(bytes);
  ASSERT_TRUE(result.report.ok());
  expect_within_half_a_step(seq, result.sequence, 2);
}

// The frame-at-a-time coder's units, back to back after a file's opening, are a file too.
TEST(FbaFile, AccessUnitsBackToBackDecodeAsAFile) {
  std::mt19937_64 rng(test_seed(kFbaSeed));
  const FapSequence seq = sequence_of(test::smooth_track(rng, lip_jaw_tongue_mask(), 60, 300));
  for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    SCOPED_TRACE(fba_profile_name(profile));
    FbaFrameEncoder encoder(encoder_options(profile, 0, 25), seq.rate);
    std::vector<std::uint8_t> bytes;
    if (profile == FbaProfile::kStandard) {
      bytes = {0, 0, 1, 0xBA, 0x7F};
    } else {
      const auto opening = fba_fapcast_opening();
      bytes.assign(opening.begin(), opening.end());
    }
    std::vector<std::size_t> units;
    for (const FapFrame& f : seq.frames) {
      FbaAccessUnit unit;
      ASSERT_FALSE(encoder.encode(f, unit));
      units.push_back(bytes.size());
      bytes.insert(bytes.end(), unit.bytes.begin(), unit.bytes.end());
    }
    bytes.insert(bytes.end(), {0, 0, 1, 0xB1});
    const auto result = decode_fba(bytes);
    ASSERT_TRUE(result.report.ok()) << result.report.errors.front().message();
    EXPECT_EQ(result.sequence, seq);
    // Unit 30 cut short: it and the P units up to the next intra unit (50) are lost, one error in all.
    bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(units[31] - 2), bytes.begin() + static_cast<std::ptrdiff_t>(units[31]));
    const auto lossy = decode_fba(bytes);
    EXPECT_EQ(lossy.report.errors_total, 1u);
    EXPECT_EQ(lossy.report.frames_decoded, 40u);
    EXPECT_EQ(lossy.report.frames_lost, 20u);  // fapcast: by frame number; standard: the planes met
    ASSERT_EQ(lossy.sequence.frames.size(), 60u);
    EXPECT_EQ(lossy.sequence.frames[40], seq.frames[29]);
    EXPECT_EQ(lossy.sequence.frames[50], seq.frames[50]);
  }
}

// Stuffing: a stream rich in zero bits round-trips, and no 23 zeros occur inside it.
TEST(FbaFile, StuffingPreventsStartCodeEmulation) {
  // Downward steps to the bottom of wide ranges: long runs of 0 bits in the coded symbols.
  std::vector<FapFrame> frames(30);
  for (std::size_t k = 0; k < frames.size(); ++k)
    for (int n = 3; n <= 68; ++n) frames[k].set(n, k % 2 == 1 ? 1800 : 0);
  const FapSequence seq = sequence_of(frames);
  for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    SCOPED_TRACE(fba_profile_name(profile));
    FbaEncodeStats stats;
    const auto bytes = encode_fba(seq, encoder_options(profile, 0, 100), &stats);
    int run = 0, longest = 0;
    std::size_t start_codes = 0;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      if (i + 3 < bytes.size() && bytes[i] == 0 && bytes[i + 1] == 0 && bytes[i + 2] == 1) {
        ++start_codes;
        i += 3;
        run = 0;
        continue;
      }
      for (int b = 7; b >= 0; --b) {
        run = (bytes[i] >> b) & 1 ? 0 : run + 1;
        longest = std::max(longest, run);
      }
    }
    EXPECT_EQ(start_codes, 3u + stats.not_read_alike);  // opening + one run + end
    EXPECT_EQ(longest, 22);                             // reached, and stuffed
    EXPECT_EQ(decode_alike(bytes, stats, profile).sequence, seq);
  }
}

class FbaIntraPeriod : public ::testing::TestWithParam<int> {};

// The file encoder puts an intra plane every intra_period frames, and at every mask change.
TEST_P(FbaIntraPeriod, HonouredAndMaskChangesForceIntra) {
  const int period = GetParam();
  std::mt19937_64 rng(test_seed(kFbaSeed));
  auto frames = test::smooth_track(rng, lip_jaw_tongue_mask(), 100, 200);
  for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    const auto plain = encode_fba(sequence_of(frames), encoder_options(profile, 1, period));
    std::vector<std::size_t> expected;
    for (std::size_t k = 0; k < 100; k += static_cast<std::size_t>(period)) expected.push_back(k);
    EXPECT_EQ(run_first_frames(plain), expected);
  }
  // Drop FAP 3 from frame 37 on: frame 37 must be intra, and the period restarts there.
  for (std::size_t k = 37; k < 100; ++k) frames[k].mask.set(3, false), frames[k].values[2] = 0;
  for (const FbaProfile profile : {FbaProfile::kStandard, FbaProfile::kFapcast}) {
    const auto changed = encode_fba(sequence_of(frames), encoder_options(profile, 1, period));
    const auto planes = run_first_frames(changed);
    EXPECT_NE(std::find(planes.begin(), planes.end(), 37u), planes.end());
    for (std::size_t i = 1; i < planes.size(); ++i) EXPECT_LE(planes[i] - planes[i - 1], static_cast<std::size_t>(period));
    EXPECT_EQ(decode_fba(changed).sequence.frames[50].mask, frames[50].mask);
  }
}

INSTANTIATE_TEST_SUITE_P(Periods, FbaIntraPeriod, ::testing::Values(1, 7, 25, 1000));

TEST(FbaFile, EmptySequenceIsTheOpeningAndTheEndCode) {
  const auto bytes = encode_fba(sequence_of({}), {});
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{0, 0, 1, 0xBA, 0x7F, 0, 0, 1, 0xB1}));
  const auto result = decode_fba(bytes);
  EXPECT_TRUE(result.report.ok());
  EXPECT_TRUE(result.sequence.frames.empty());
  const auto fapcast = encode_fba(sequence_of({}), encoder_options(FbaProfile::kFapcast, 0));
  const auto opening = fba_fapcast_opening();
  EXPECT_TRUE(std::equal(opening.begin(), opening.end(), fapcast.begin()));
  EXPECT_EQ(fapcast.size(), opening.size() + 5);  // stuffing, then the end code
  EXPECT_TRUE(decode_fba(fapcast).report.ok());
}

// The fapcast profile opens with user data, not the object start code: a standard decoder finds
// no FBA object at all, and fapcast's standard-only path refuses it at byte 0 with the reason.
TEST(FbaFile, StandardOnlyPathRefusesTheFapcastProfileAtItsFirstBytes) {
  std::mt19937_64 rng(test_seed(kFbaSeed));
  const FapSequence seq = sequence_of(test::smooth_track(rng, lip_jaw_tongue_mask(), 30, 300));
  const auto bytes = encode_fba(seq, encoder_options(FbaProfile::kFapcast, 0));
  EXPECT_EQ(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + 12),
            (std::vector<std::uint8_t>{0, 0, 1, 0xB2, 'f', 'a', 'p', 'c', 'a', 's', 't', 1}));
  for (std::size_t i = 0; i + 3 < bytes.size(); ++i)
    EXPECT_FALSE(bytes[i] == 0 && bytes[i + 1] == 0 && bytes[i + 2] == 1 && bytes[i + 3] == 0xBA) << "at " << i;
  EXPECT_EQ(fba_file_profile(bytes), FbaProfile::kFapcast);
  FbaDecodeOptions standard_only;
  standard_only.standard_only = true;
  const auto refused = decode_fba(bytes, standard_only);
  ASSERT_EQ(refused.report.errors_total, 1u);
  EXPECT_EQ(refused.report.errors[0].byte_offset, 0u);
  EXPECT_EQ(refused.report.errors[0].code, fba_errc::fapcast_profile);
  EXPECT_EQ(refused.report.errors[0].message().substr(0, 24), "byte 0: fapcast-profile:");
  EXPECT_TRUE(refused.sequence.frames.empty());
  EXPECT_EQ(decode_fba(bytes).sequence, seq);  // the default path reads both
  auto later = bytes;
  later[11] = 2;  // a profile version this decoder does not know
  EXPECT_EQ(decode_fba(later).report.errors.at(0).code, fba_errc::bad_profile_version);
}

TEST(FbaFile, GarbageIsReportedNeverThrown) {
  std::mt19937_64 rng(test_seed(kFbaSeed));
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::uint8_t> bytes(rng() % 200);
    for (auto& b : bytes) b = static_cast<std::uint8_t>(rng() % 4 == 0 ? 0 : rng());
    if (trial % 3 == 1 && bytes.size() >= 4) bytes[0] = 0, bytes[1] = 0, bytes[2] = 1, bytes[3] = 0xBA;
    if (trial % 3 == 2 && bytes.size() >= 12) std::copy(fba_fapcast_opening().begin(), fba_fapcast_opening().end(), bytes.begin());
    const auto result = decode_fba(bytes);
    EXPECT_FALSE(result.report.ok());
    EXPECT_EQ(result.sequence.frames.size(), result.report.frames_decoded + result.report.frames_lost + result.report.frames_skipped);
  }
}

// fapcast's P predictors (spec/fba.md §10) are exact where the spec says so.
TEST(FbaPrediction, ExactForAConstantPlusASinusoidAndForQuadratics) {
  // cos w = 1/2: (k - 7) / 8 = 1 + 2 cos w = 2, k = 23; x[n] = x[n-3] + 2 (x[n-1] - x[n-2]).
  std::vector<std::int32_t> x{100, 143, 143};
  for (int n = 3; n < 40; ++n) x.push_back(x[n - 3] + 2 * (x[n - 1] - x[n - 2]));
  for (std::size_t n = 3; n < x.size(); ++n) EXPECT_EQ(fba_predict(23, x[n - 1], x[n - 2], x[n - 3]), x[n]) << n;
  for (std::int32_t n = 3; n < 40; ++n)
    EXPECT_EQ(fba_predict(31, (n - 1) * (n - 1), (n - 2) * (n - 2), (n - 3) * (n - 3)), n * n) << n;
  EXPECT_EQ(fba_predict(0, 5, 900, -900), 5);  // predictor 0: the previous value
  EXPECT_EQ(fba_predict(31, 2147483647, -2147483647, 2147483647), 2147483647);  // saturates
  EXPECT_EQ(fba_reference_part(16, -7), -7);   // c = 1: the reference's level itself
  EXPECT_EQ(fba_reference_part(8, 3), 2);      // 1.5 rounds half up
  EXPECT_EQ(fba_reference_part(-24, 5), -7);   // -7.5 rounds half up
}

// On a smooth rhythmic track the fapcast encoder chooses predictors, the file shrinks, and every
// value still comes back within step/2.
TEST(FbaPrediction, ChosenPredictorsShrinkARhythmicTrackWithinHalfAStep) {
  std::vector<FapFrame> frames(500);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    for (int n = 3; n <= 18; ++n) {
      const double w = 0.9 + 0.02 * n;  // 3.6..4.3 Hz at 25 fps
      frames[k].set(n, static_cast<std::int32_t>(std::lround(60 + 120 * std::sin(w * static_cast<double>(k) + n))));
    }
  }
  const FapSequence seq = sequence_of(frames);
  for (const int q : {0, 1, 4}) {
    const auto chosen = encode_fba(seq, encoder_options(FbaProfile::kFapcast, q));
    FbaEncoderOptions plain_options = encoder_options(FbaProfile::kFapcast, q);
    plain_options.choose_predictors = false;
    const auto plain = encode_fba(seq, plain_options);
    EXPECT_LT(static_cast<double>(chosen.size()), 0.85 * static_cast<double>(plain.size())) << "q " << q;
    const auto result = decode_fba(chosen);
    ASSERT_TRUE(result.report.ok());
    expect_within_half_a_step(seq, result.sequence, q);
  }
}

// Right-side FAPs predicted from the left: on a symmetric track (left and right equal, as in
// `say` output) the references halve what the paired FAPs cost, losslessly.
TEST(FbaPrediction, RightFromLeftOnASymmetricTrack) {
  std::mt19937_64 rng(test_seed(kFbaSeed));
  FapMask left;
  for (const int n : {6, 8, 10, 12, 19, 21, 39, 41, 53, 55, 57, 59}) left.set(n);
  std::vector<FapFrame> frames = test::smooth_track(rng, left, 400, 600);
  for (FapFrame& f : frames)
    for (const int n : {6, 8, 10, 12, 19, 21, 39, 41, 53, 55, 57, 59}) f.set(n + 1, f.value(n));
  const FapSequence seq = sequence_of(frames);
  const auto symmetric = encode_fba(seq, encoder_options(FbaProfile::kFapcast, 0));
  const auto one_side = encode_fba(sequence_of(test::smooth_track(rng, left, 400, 600)), encoder_options(FbaProfile::kFapcast, 0));
  EXPECT_LT(static_cast<double>(symmetric.size()), 1.15 * static_cast<double>(one_side.size()));
  EXPECT_EQ(decode_fba(symmetric).sequence, seq);
}

}  // namespace
}  // namespace fapcast
