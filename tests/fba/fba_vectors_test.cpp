// The standard-syntax conformance vectors (tests/data/fba/vectors, written by an independent
// encoder): every one decodes to its .fap exactly, under the reference stuffing reading and the
// published decoder's fixed give-back alike; and fapcast's own standard encoding of each decoded
// track decodes back the same way.
#include "fapcast/codec/fap_text.hpp"
#include "fapcast/fba/fba_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/file_bytes.hpp"

namespace fapcast {
namespace {

namespace fs = std::filesystem;
const fs::path kVectors = fs::path(FAPCAST_TEST_DATA) / "fba" / "vectors";

using test::slurp;
using test::read_bytes;

struct Vector {
  const char* name;
  FrameRate rate;
  int fap_quant;
};

class FbaVectors : public testing::TestWithParam<Vector> {};

TEST_P(FbaVectors, DecodeExactlyToTheirFap) {
  const Vector& v = GetParam();
  const auto bytes = read_bytes(kVectors / (std::string(v.name) + ".fba"));
  const fs::path fap = kVectors / (std::string(v.name) + ".fap");
  const FapSequence expected = read_fap_text(slurp(fap), fap.string()).sequence;
  for (const bool fixed : {false, true}) {
    SCOPED_TRACE(fixed ? "fixed give-back of 14 raw bits" : "consumed bits given back");
    FbaDecodeOptions options;
    options.fixed_give_back = fixed;
    const FbaDecodeResult r = decode_fba(bytes, options);
    ASSERT_TRUE(r.report.ok()) << r.report.errors.front().message();
    EXPECT_EQ(r.report.profile, FbaProfile::kStandard);
    EXPECT_EQ(r.report.stuffing, FbaStuffing::kReference);
    EXPECT_EQ(r.report.fap_quant, v.fap_quant);
    EXPECT_TRUE(r.report.rate_known);
    EXPECT_EQ(r.report.time_code_mismatches, 0u);
    EXPECT_EQ(r.sequence.rate, v.rate);
    ASSERT_EQ(r.sequence.frames.size(), expected.frames.size());
    for (std::size_t k = 0; k < expected.frames.size(); ++k) ASSERT_EQ(r.sequence.frames[k], expected.frames[k]) << "frame " << k;
  }
}

TEST_P(FbaVectors, FapcastsStandardEncodingOfTheTrackReadsBackAlike) {
  const Vector& v = GetParam();
  const fs::path fap = kVectors / (std::string(v.name) + ".fap");
  FapSequence track = read_fap_text(slurp(fap), fap.string()).sequence;
  track.rate = v.rate;
  FbaEncoderOptions o;
  o.fap_quant = v.fap_quant;
  const auto bytes = encode_fba(track, o);
  for (const auto stuffing : {FbaStuffing::kReference, FbaStuffing::kContinuous}) {
    FbaDecodeOptions options;
    options.stuffing = stuffing;
    const FbaDecodeResult r = decode_fba(bytes, options);
    ASSERT_TRUE(r.report.ok()) << r.report.errors.front().message();
    ASSERT_EQ(r.sequence.frames.size(), track.frames.size());
    // The vector's values sit on its own quantiser grid, which re-quantising keeps.
    for (std::size_t k = 0; k < track.frames.size(); ++k) ASSERT_EQ(r.sequence.frames[k], track.frames[k]) << "frame " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Independent, FbaVectors,
                         testing::Values(Vector{"v01_minimal", {25, 1}, 1}, Vector{"v02_viseme_expression", {25, 1}, 2},
                                         Vector{"v03_masks_skips_startcodes_timecode", {25, 1}, 1},
                                         Vector{"v04_new_ranges_lossless", {25, 1}, 0}, Vector{"v05_stuffing", {25, 1}, 0},
                                         Vector{"v06_ntsc_tight_allfaps", {30000, 1001}, 5}),
                         [](const auto& info) { return std::string(info.param.name).substr(0, 3); });

}  // namespace
}  // namespace fapcast
