#include "fapcast/corpus/c3d.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/synthetic_label.hpp"
#include "corpus/corpus_test_support.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

using test::corpus_data;
using test::file_bytes;

class C3dRoundTrip : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(C3dRoundTrip, FloatPositionsReadBackExactly) {
  const std::uint64_t seed = test::test_seed(test::kCorpusSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  const auto [frames, markers] = GetParam();
  MarkerFrames<Millimetres> m = test::random_markers(rng, frames, markers);
  m.frame_rate_hz = 59.94f;  // a float rate survives exactly
  const std::string bytes = write_c3d(m, {c3d_synthetic_parameter(), {"SESSION", "ACTOR", "ref talker", ""}});
  EXPECT_EQ(bytes.size() % 512, 0u);
  const C3dFile back = read_c3d(bytes, "round.c3d");
  EXPECT_EQ(back.markers, m);
  EXPECT_TRUE(back.float_storage);
  EXPECT_EQ(back.units, "mm");
  EXPECT_EQ(back.text_parameters.at("FAPCAST:SYNTHETIC"), kSyntheticLabel);
  EXPECT_EQ(back.text_parameters.at("SESSION:ACTOR"), "ref talker");
  EXPECT_EQ(write_c3d(back.markers, {c3d_synthetic_parameter(), {"SESSION", "ACTOR", "ref talker", ""}}), bytes);
}

// Sizes around the block boundaries and the 255-labels-per-parameter split.
INSTANTIATE_TEST_SUITE_P(Shapes, C3dRoundTrip,
                         ::testing::Values(std::pair{0, 0}, std::pair{1, 1}, std::pair{120, 40},
                                           std::pair{3, 255}, std::pair{2, 256}, std::pair{2, 600}));

TEST(C3d, ReadsIntegerStorageWithAnalogAndEvents) {
  // Written by make_c3d_fixtures.py: raw x = 10p + f, y = -3p, z = 100 + f, scale 0.5 mm; 8
  // analog samples follow each frame (2 channels x 4), so a wrong skip shifts every later frame.
  const C3dFile c = read_c3d(file_bytes(corpus_data() / "good/int_analog.c3d"), "int_analog.c3d");
  EXPECT_FALSE(c.float_storage);
  EXPECT_EQ(c.point_scale, 0.5);
  const MarkerFrames<Millimetres>& m = c.markers;
  EXPECT_EQ(m.labels, (std::vector<std::string>{"8.1", "8.2", "HEAD_L"}));
  EXPECT_EQ(m.frame_rate_hz, 60.0);
  ASSERT_EQ(m.frame_count(), 5);
  for (Eigen::Index f = 0; f < 5; ++f) {
    for (Eigen::Index p = 0; p < 3; ++p) {
      if (f == 2 && p == 1) {
        EXPECT_FALSE(m.present(p, f));
        continue;
      }
      EXPECT_TRUE(m.present(p, f));
      EXPECT_EQ(m.at(p, f), Eigen::Vector3d(10.0 * p + f, -3.0 * p, 100.0 + f) * 0.5) << f << "," << p;
    }
  }
}

TEST(C3d, ConvertsMetresToMillimetres) {
  const C3dFile c = read_c3d(file_bytes(corpus_data() / "good/float_metres.c3d"), "float_metres.c3d");
  EXPECT_EQ(c.units, "m");
  EXPECT_EQ(c.markers.frame_rate_hz, 100.0);
  EXPECT_EQ(c.markers.at(2, 3), Eigen::Vector3d(23000, -6000, 103000));
}

TEST(C3d, ReadsLabelsContinuedInLabels2) {
  const C3dFile c = read_c3d(file_bytes(corpus_data() / "good/labels2.c3d"), "labels2.c3d");
  ASSERT_EQ(c.markers.marker_count(), 260);
  EXPECT_EQ(c.markers.labels[254], "M254");
  EXPECT_EQ(c.markers.labels[259], "M259");
  EXPECT_EQ(c.markers.find("M255"), 255);
}

TEST(C3d, EveryTruncationIsRefusedWithAnError) {
  std::mt19937_64 rng(1);
  const std::string bytes = write_c3d(test::random_markers(rng, 20, 5), {c3d_synthetic_parameter()});
  const std::size_t data_block = static_cast<unsigned char>(bytes[16]) | static_cast<unsigned char>(bytes[17]) << 8;
  const std::size_t data_end = (data_block - 1) * 512 + 20 * 5 * 16;
  for (std::size_t n = 0; n < data_end; n += 7) {
    // Zero padding after the data may go; anything shorter than the data must not.
    EXPECT_THROW(read_c3d(bytes.substr(0, n), "cut.c3d"), InputError) << n;
  }
}

TEST(C3d, FlippedBytesNeverCrash) {
  // Every single-byte change of the header and parameters either reads or throws InputError.
  std::mt19937_64 rng(2);
  const std::string good = write_c3d(test::random_markers(rng, 4, 3), {c3d_synthetic_parameter()});
  for (std::size_t at = 0; at < 1536; ++at) {
    std::string bad = good;
    bad[at] = static_cast<char>(bad[at] ^ 0xA5);
    try {
      (void)read_c3d(bad, "flip.c3d");
    } catch (const InputError&) {
    }
  }
}

TEST(C3d, WriterRefusesWhatC3dCannotHold) {
  EXPECT_THROW(write_c3d(MarkerFrames<Millimetres>::zeros(0, 65536)), std::invalid_argument);
  MarkerFrames<Millimetres> unnamed = MarkerFrames<Millimetres>::zeros(1, 1);
  EXPECT_THROW(write_c3d(unnamed), std::invalid_argument);
  unnamed.labels[0] = "A";
  EXPECT_THROW(write_c3d(unnamed, {{"point", "X", "lower-case group", ""}}), std::invalid_argument);
  EXPECT_NO_THROW(write_c3d(unnamed));
  unnamed.positions(1, 0) = 1e39;  // beyond float range
  EXPECT_THROW(write_c3d(unnamed), std::invalid_argument);
}

// Inputs the fuzzer once crashed on (tests/data/corpus/fuzz-regressions/c3d.NNN.<what>.c3d):
// each reads or is refused, and what reads either re-writes and reads back or is refused by the
// writer with std::invalid_argument, the property c3d_fuzz checks.
TEST(C3d, FuzzRegressions) {
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(corpus_data() / "fuzz-regressions")) {
    if (e.path().extension() != ".c3d") continue;
    ++files;
    SCOPED_TRACE(e.path().filename().string());
    C3dFile c;
    try {
      c = read_c3d(file_bytes(e.path()), e.path().filename().string());
    } catch (const InputError&) {
      continue;
    }
    std::string again;
    try {
      again = write_c3d(c.markers);
    } catch (const std::invalid_argument&) {
      continue;
    }
    EXPECT_EQ(read_c3d(again, "again").markers.labels, c.markers.labels);
  }
  EXPECT_GE(files, 1);
}

}  // namespace
}  // namespace fapcast
