// Guarantees of the whole-file FBA coder (spec/fba.md), each a test.
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

using test::fba_seed;
using test::reproduce;

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

FbaDecodeResult round_trip(const FapSequence& seq, FbaEncoderOptions o) {
  const auto bytes = encode_fba(seq, o);
  return decode_fba(bytes);
}

// At fap_quant 0 every value inside +/-1860 comes back exactly, on every low-level FAP.
TEST(FbaFile, LosslessAtQuantZeroOverTheWholeCodableRange) {
  const std::uint64_t seed = fba_seed();
  SCOPED_TRACE(reproduce(seed, "FbaFile.LosslessAtQuantZeroOverTheWholeCodableRange"));
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> value(-1860, 1860);
  std::vector<FapFrame> frames(60);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) frames[k].set(n, value(rng));
  }
  frames[0].set(3, 1860).set(4, -1860);  // both ends of the range
  frames[1].set(3, -1860).set(4, 1860);  // and a P difference of 3720
  const FapSequence seq = sequence_of(frames);
  const auto result = round_trip(seq, {0, 25});
  ASSERT_TRUE(result.report.ok()) << result.report.errors.front().message();
  EXPECT_EQ(result.sequence, seq);
}

// A value one unit beyond the range is refused, naming frame and FAP; never clipped.
TEST(FbaFile, ValueBeyond1860IsRefusedNotClipped) {
  for (const std::int32_t bad : {1861, -1861, 100000}) {
    std::vector<FapFrame> frames(5);
    for (auto& f : frames) f.set(48, 10);
    frames[3].set(48, bad);
    try {
      encode_fba(sequence_of(frames), {0, 25});
      FAIL() << bad << " was accepted";
    } catch (const FbaEncodeError& e) {
      EXPECT_EQ(e.code(), fba_errc::uncodable_value);
      const std::string what = e.what();
      EXPECT_NE(what.find("frame 3"), std::string::npos) << what;
      EXPECT_NE(what.find("FAP 48 head_pitch"), std::string::npos) << what;
      EXPECT_NE(what.find(std::to_string(bad)), std::string::npos) << what;
      EXPECT_NE(what.find("never clipped"), std::string::npos) << what;
    }
  }
}

TEST(FbaFile, InvalidOptionsAreTheCallersMistake) {
  const FapSequence seq = sequence_of({FapFrame{}.set(3, 1)});
  for (const FbaEncoderOptions o : {FbaEncoderOptions{-1, 25}, FbaEncoderOptions{32, 25}, FbaEncoderOptions{1, 0}}) {
    try {
      encode_fba(seq, o);
      FAIL();
    } catch (const FbaEncodeError& e) {
      EXPECT_EQ(e.code(), std::errc::invalid_argument);
    }
  }
}

struct QuantCase {
  int fap_quant;
  std::size_t frames;
};
class FbaQuantised : public ::testing::TestWithParam<QuantCase> {};

// With fap_quant q every decoded value is within step/2 of the input, with no drift.
// (The long run at two quantisers keeps the suite fast under ASan.)
TEST_P(FbaQuantised, WithinHalfAStepWithoutDrift) {
  const int q = GetParam().fap_quant;
  const std::uint64_t seed = fba_seed() + static_cast<std::uint64_t>(q);
  SCOPED_TRACE(reproduce(seed - static_cast<std::uint64_t>(q), "Quant/FbaQuantised.*"));
  std::mt19937_64 rng(seed);
  FapMask mask;
  mask.set(3).set(5).set(48);  // small mask: the test stays fast under ASan
  const FapSequence seq = sequence_of(test::smooth_track(rng, mask, GetParam().frames, 800));
  const auto result = round_trip(seq, {q, 250});
  ASSERT_TRUE(result.report.ok());
  ASSERT_EQ(result.sequence.frames.size(), seq.frames.size());
  std::int64_t worst_excess = 0;
  for (std::size_t k = 0; k < seq.frames.size(); ++k) {
    for (int n : {3, 5, 48}) {
      const std::int64_t error = std::abs(std::int64_t{result.sequence.frames[k].value(n)} - seq.frames[k].value(n));
      worst_excess = std::max(worst_excess, 2 * error - fba_step(n, q));  // 2*error <= step
    }
  }
  EXPECT_LE(worst_excess, 0);
}

INSTANTIATE_TEST_SUITE_P(Quant, FbaQuantised,
                         ::testing::Values(QuantCase{1, 100000}, QuantCase{2, 10000}, QuantCase{4, 10000},
                                           QuantCase{8, 100000}, QuantCase{31, 10000}));

// Random sequences of every shape round-trip within step/2: random masks, rates, quants.
TEST(FbaFile, RandomRoundTrips) {
  const std::uint64_t seed = fba_seed();
  SCOPED_TRACE(reproduce(seed, "FbaFile.RandomRoundTrips"));
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    FapMask mask;
    for (int n = 1; n <= kFapCount; ++n) mask.set(n, rng() % 3 == 0);
    const int q = static_cast<int>(rng() % 9);
    auto frames = test::smooth_track(rng, mask, 1 + rng() % 120, 1 + static_cast<int>(rng() % 1800) / std::max(q, 1));
    for (auto& f : frames) {
      if (f.mask.test(1)) f.viseme = {static_cast<std::uint8_t>(rng() % 15), static_cast<std::uint8_t>(rng() % 15), static_cast<std::uint8_t>(rng() % 64), rng() % 2 == 0};
      if (f.mask.test(2)) f.expression = {static_cast<std::uint8_t>(rng() % 7), static_cast<std::uint8_t>(rng() % 64), static_cast<std::uint8_t>(rng() % 7), static_cast<std::uint8_t>(rng() % 64), rng() % 2 == 0, rng() % 2 == 0};
      if (rng() % 50 == 0) f.mask.set(3 + static_cast<int>(rng() % 66), false);  // a mask change
      for (int n = 3; n <= kFapCount; ++n) {
        if (!f.mask.test(n)) f.values[static_cast<std::size_t>(n - 1)] = 0;
      }
    }
    const FapSequence seq = sequence_of(frames, rng() % 2 ? FrameRate{25, 1} : FrameRate{30000, 1001});
    const auto result = round_trip(seq, {q, 1 + static_cast<int>(rng() % 30)});
    ASSERT_TRUE(result.report.ok()) << result.report.errors.front().message();
    ASSERT_EQ(result.sequence.frames.size(), seq.frames.size());
    EXPECT_EQ(result.sequence.rate, seq.rate);
    for (std::size_t k = 0; k < seq.frames.size(); ++k) {
      const FapFrame& in = seq.frames[k];
      const FapFrame& out = result.sequence.frames[k];
      ASSERT_EQ(out.mask, in.mask) << "frame " << k;
      if (in.mask.test(1)) {
        ASSERT_EQ(out.viseme, in.viseme);
      }
      if (in.mask.test(2)) {
        ASSERT_EQ(out.expression, in.expression);
      }
      for (int n = 3; n <= kFapCount; ++n) {
        ASSERT_LE(2 * std::abs(std::int64_t{out.value(n)} - in.value(n)), fba_step(n, q)) << "frame " << k << " FAP " << n;
      }
    }
  }
}

// The byte offsets of the runs of a file (each opens with a plane start code).
std::vector<std::size_t> run_offsets(const std::vector<std::uint8_t>& b) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i + 3 < b.size(); ++i)
    if (b[i] == 0 && b[i + 1] == 0 && b[i + 2] == 1 && b[i + 3] == 0xBB) out.push_back(i);
  return out;
}

// The first frame of each run: each run decoded alone (object start code, run, end code).
std::vector<std::size_t> run_first_frames(const std::vector<std::uint8_t>& b) {
  const auto runs = run_offsets(b);
  std::vector<std::size_t> out;
  std::size_t frame = 0;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    std::vector<std::uint8_t> one{0, 0, 1, 0xBA};
    one.insert(one.end(), b.begin() + static_cast<std::ptrdiff_t>(runs[r]),
               b.begin() + static_cast<std::ptrdiff_t>(r + 1 < runs.size() ? runs[r + 1] : b.size() - 4));
    one.insert(one.end(), {0, 0, 1, 0xB1});
    out.push_back(frame);
    frame += decode_fba(one).report.frames_decoded;
  }
  return out;
}

// After corruption the decoder resumes at the next run (its intra plane) and counts the frames
// lost from the intra plane's frame_number: a corrupt run is lost whole.
TEST(FbaFile, ResynchronisesAfterCorruptionAndCountsLostFrames) {
  std::mt19937_64 rng(fba_seed());
  const FapSequence seq = sequence_of(test::smooth_track(rng, lip_jaw_tongue_mask(), 100, 300));
  const auto good = encode_fba(seq, {0, 25});
  const auto runs = run_offsets(good);
  ASSERT_EQ(runs.size(), 4u);  // intra planes 0, 25, 50, 75, one run each
  ASSERT_EQ(run_first_frames(good), (std::vector<std::size_t>{0, 25, 50, 75}));
  const auto expect_lost = [&](const FbaDecodeResult& r, std::size_t from, std::size_t to) {
    EXPECT_EQ(r.report.frames_lost, to - from);
    EXPECT_EQ(r.report.frames_decoded, 100 - (to - from));
    ASSERT_EQ(r.sequence.frames.size(), 100u);
    for (std::size_t k = 0; k < 100; ++k) {
      if (k >= from && k < to) {
        EXPECT_EQ(r.sequence.frames[k], seq.frames[from - 1]) << "lost frames hold the last good one";
      } else {
        EXPECT_EQ(r.sequence.frames[k], seq.frames[k]) << k;
      }
    }
  };
  {
    SCOPED_TRACE("bytes cut from the middle of run 1 (frames 25..49)");
    auto bytes = good;
    const std::size_t mid = (runs[1] + runs[2]) / 2;
    bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(mid), bytes.begin() + static_cast<std::ptrdiff_t>(mid + 17));
    const auto result = decode_fba(bytes);
    ASSERT_EQ(result.report.errors_total, 1u) << result.report.errors.front().message();
    EXPECT_GE(result.report.errors[0].byte_offset, runs[1]);
    EXPECT_LT(result.report.errors[0].byte_offset, runs[2] - 17);
    expect_lost(result, 25, 50);
  }
  {
    SCOPED_TRACE("bits flipped in run 2 (frames 50..74)");
    auto bytes = good;
    for (std::size_t i = runs[2] + 40; i < runs[3] - 8; i += 9) bytes[i] ^= 0x5A;
    const auto result = decode_fba(bytes);
    ASSERT_GE(result.report.errors_total, 1u);
    expect_lost(result, 50, 75);
  }
  {
    SCOPED_TRACE("run 1 removed whole: the next intra plane's frame_number tells");
    auto bytes = good;
    bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(runs[1]), bytes.begin() + static_cast<std::ptrdiff_t>(runs[2]));
    const auto result = decode_fba(bytes);
    ASSERT_EQ(result.report.errors_total, 1u);
    EXPECT_EQ(result.report.errors[0].code, fba_errc::bad_frame_number);
    expect_lost(result, 25, 50);
  }
}

// The archival preset: an intra plane (a run, a place to enter and resume) every 20 s of frames,
// the guarantees unchanged, and corruption costing that run only.
TEST(FbaFile, ArchivePresetPutsAnIntraPlaneEveryTwentySeconds) {
  EXPECT_EQ(fba_archive_options(2, {25, 1}).intra_period, 500);
  EXPECT_EQ(fba_archive_options(2, {30000, 1001}).intra_period, 599);  // 29.97 fps, rounded down
  EXPECT_EQ(fba_archive_options(2, {1, 60}).intra_period, 1);          // one frame a minute
  EXPECT_EQ(fba_archive_options(3, {25, 1}).fap_quant, 3);
  std::mt19937_64 rng(fba_seed());
  const FapSequence seq = sequence_of(test::smooth_track(rng, lip_jaw_tongue_mask(), 1200, 600));
  const FbaEncoderOptions archive = fba_archive_options(2, seq.rate);
  const auto bytes = encode_fba(seq, archive);
  ASSERT_EQ(run_first_frames(bytes), (std::vector<std::size_t>{0, 500, 1000}));
  EXPECT_LT(bytes.size(), encode_fba(seq, {.fap_quant = 2}).size());
  const auto result = decode_fba(bytes);
  ASSERT_TRUE(result.report.ok());
  ASSERT_EQ(result.sequence.frames.size(), seq.frames.size());
  for (std::size_t k = 0; k < seq.frames.size(); ++k) {
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
      if (!seq.frames[k].mask.test(n)) continue;
      ASSERT_LE(std::abs(result.sequence.frames[k].value(n) - seq.frames[k].value(n)), fba_step(n, 2) / 2) << k << " " << n;
    }
  }
  auto corrupt = bytes;
  const auto runs = run_offsets(bytes);
  corrupt[(runs[1] + runs[2]) / 2] ^= 0x5A;
  const auto damaged = decode_fba(corrupt);
  EXPECT_EQ(damaged.report.frames_lost, 500u);  // the run of frames 500..999, no more
  EXPECT_EQ(damaged.sequence.frames[1000], result.sequence.frames[1000]);
}

// The frame-at-a-time coder's units, back to back, are a file too (one plane per run).
TEST(FbaFile, AccessUnitsBackToBackDecodeAsAFile) {
  std::mt19937_64 rng(fba_seed());
  const FapSequence seq = sequence_of(test::smooth_track(rng, lip_jaw_tongue_mask(), 60, 300));
  FbaFrameEncoder encoder({0, 25}, seq.rate);
  std::vector<std::uint8_t> bytes{0, 0, 1, 0xBA};
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
  // Units 30..34 lost: the P units up to the next intra unit (50) are refused, one error in all.
  bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(units[30]), bytes.begin() + static_cast<std::ptrdiff_t>(units[35]));
  const auto lossy = decode_fba(bytes);
  EXPECT_EQ(lossy.report.errors_total, 1u);
  EXPECT_EQ(lossy.report.frames_lost, 20u);
  EXPECT_EQ(lossy.report.frames_decoded, 40u);
  ASSERT_EQ(lossy.sequence.frames.size(), 60u);
  EXPECT_EQ(lossy.sequence.frames[50], seq.frames[50]);
}

// Stuffing: a stream rich in zero bits round-trips, and no 23 zeros occur inside it.
TEST(FbaFile, StuffingPreventsStartCodeEmulation) {
  // Downward steps make the P range [-1000, 0], so a zero difference is the lowest interval
  // and codes as a long run of 0 bits.
  std::vector<FapFrame> frames(30);
  for (std::size_t k = 0; k < frames.size(); ++k)
    for (int n = 3; n <= 18; ++n) frames[k].set(n, k == 1 ? -1000 : (k >= 2 ? -1000 : 0));
  const FapSequence seq = sequence_of(frames);
  const auto bytes = encode_fba(seq, {0, 100});
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
  EXPECT_EQ(start_codes, 3u);   // object + one run of 30 planes + end
  EXPECT_EQ(longest, 22);       // reached, and stuffed
  const auto result = decode_fba(bytes);
  ASSERT_TRUE(result.report.ok()) << result.report.errors.front().message();
  EXPECT_EQ(result.sequence, seq);
}

class FbaIntraPeriod : public ::testing::TestWithParam<int> {};

// The file encoder puts an intra plane every intra_period frames, and at every mask change.
TEST_P(FbaIntraPeriod, HonouredAndMaskChangesForceIntra) {
  const int period = GetParam();
  std::mt19937_64 rng(fba_seed());
  auto frames = test::smooth_track(rng, lip_jaw_tongue_mask(), 100, 200);
  const auto plain = encode_fba(sequence_of(frames), {1, period});
  std::vector<std::size_t> expected;
  for (std::size_t k = 0; k < 100; k += static_cast<std::size_t>(period)) expected.push_back(k);
  EXPECT_EQ(run_first_frames(plain), expected);
  // Drop FAP 3 from frame 37 on: frame 37 must be intra, and the period restarts there.
  for (std::size_t k = 37; k < 100; ++k) frames[k].mask.set(3, false), frames[k].values[2] = 0;
  const auto changed = encode_fba(sequence_of(frames), {1, period});
  const auto planes = run_first_frames(changed);
  EXPECT_NE(std::find(planes.begin(), planes.end(), 37u), planes.end());
  for (std::size_t i = 1; i < planes.size(); ++i) EXPECT_LE(planes[i] - planes[i - 1], static_cast<std::size_t>(period));
  EXPECT_EQ(decode_fba(changed).sequence.frames[50].mask, frames[50].mask);
}

INSTANTIATE_TEST_SUITE_P(Periods, FbaIntraPeriod, ::testing::Values(1, 7, 25, 1000));

TEST(FbaFile, EmptySequenceIsObjectAndEndCodes) {
  const auto bytes = encode_fba(sequence_of({}), {});
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{0, 0, 1, 0xBA, 0, 0, 1, 0xB1}));
  const auto result = decode_fba(bytes);
  EXPECT_TRUE(result.report.ok());
  EXPECT_TRUE(result.sequence.frames.empty());
}

TEST(FbaFile, GarbageIsReportedNeverThrown) {
  std::mt19937_64 rng(fba_seed());
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::uint8_t> bytes(rng() % 200);
    for (auto& b : bytes) b = static_cast<std::uint8_t>(rng() % 4 == 0 ? 0 : rng());
    const auto result = decode_fba(bytes);
    EXPECT_FALSE(result.report.ok());
    EXPECT_EQ(result.sequence.frames.size(), result.report.frames_decoded + result.report.frames_lost + result.report.frames_skipped);
  }
}

}  // namespace
}  // namespace fapcast

namespace fapcast {
namespace {

// fapcast's P predictors (spec/fba.md §6) are exact where the spec says so.
TEST(FbaPrediction, ExactForAConstantPlusASinusoidAndForQuadratics) {
  // cos w = 1/2: (k - 7) / 8 = 1 + 2 cos w = 2, k = 23; x[n] = x[n-3] + 2 (x[n-1] - x[n-2]).
  std::vector<std::int32_t> x{100, 143, 143};
  for (int n = 3; n < 40; ++n) x.push_back(x[n - 3] + 2 * (x[n - 1] - x[n - 2]));
  for (std::size_t n = 3; n < x.size(); ++n) EXPECT_EQ(fba_predict(23, x[n - 1], x[n - 2], x[n - 3]), x[n]) << n;
  for (std::int32_t n = 3; n < 40; ++n)
    EXPECT_EQ(fba_predict(31, (n - 1) * (n - 1), (n - 2) * (n - 2), (n - 3) * (n - 3)), n * n) << n;
  EXPECT_EQ(fba_predict(0, 5, 900, -900), 5);  // predictor 0: the previous value
  EXPECT_EQ(fba_predict(31, 2147483647, -2147483647, 2147483647), 2147483647);  // saturates
}

// On a smooth rhythmic track the encoder chooses predictors, the file shrinks, and every value
// still comes back within step/2.
TEST(FbaPrediction, ChosenPredictorsShrinkARhythmicTrackWithinHalfAStep) {
  std::vector<FapFrame> frames(500);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    for (int n = 3; n <= 18; ++n) {
      const double w = 0.9 + 0.02 * n;  // 3.6..4.3 Hz at 25 fps
      frames[k].set(n, static_cast<std::int32_t>(std::lround(60 + 120 * std::sin(w * static_cast<double>(k) + n))));
    }
  }
  const FapSequence seq = sequence_of(frames);
  for (const int q : {1, 4}) {
    const auto chosen = encode_fba(seq, {.fap_quant = q});
    const auto plain = encode_fba(seq, {.fap_quant = q, .choose_predictors = false});
    EXPECT_LT(static_cast<double>(chosen.size()), 0.85 * static_cast<double>(plain.size())) << "q " << q;
    const auto result = decode_fba(chosen);
    ASSERT_TRUE(result.report.ok());
    ASSERT_EQ(result.sequence.frames.size(), frames.size());
    for (std::size_t k = 0; k < frames.size(); ++k)
      for (int n = 3; n <= 18; ++n)
        ASSERT_LE(2 * std::abs(result.sequence.frames[k].value(n) - frames[k].value(n)), fba_step(n, q)) << k << " " << n;
  }
}

}  // namespace
}  // namespace fapcast
