// TRC and marker CSV: fixtures, round trips, and agreement with C3D on the same marker set.
#include "fapcast/corpus/c3d.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/marker_csv.hpp"
#include "fapcast/corpus/trc.hpp"
#include "corpus/corpus_test_support.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

using test::corpus_data;
using test::file_bytes;

TEST(Trc, ReadsHandWrittenFileInMetres) {
  const MarkerFrames<Millimetres> m = read_trc(file_bytes(corpus_data() / "good/hand.trc"), "hand.trc");
  EXPECT_EQ(m.labels, (std::vector<std::string>{"8.3", "HEAD_R"}));
  EXPECT_EQ(m.frame_rate_hz, 60.0);
  ASSERT_EQ(m.frame_count(), 3);
  EXPECT_DOUBLE_EQ(m.at(0, 0).x(), 12.5);
  EXPECT_DOUBLE_EQ(m.at(0, 0).y(), -31.0);
  EXPECT_FALSE(m.present(1, 1));  // trailing cells left empty
  EXPECT_TRUE(m.present(1, 2));
  EXPECT_DOUBLE_EQ(m.at(1, 2).z(), 50.0);
}

TEST(MarkerCsv, ReadsHandWrittenFile) {
  const MarkerFrames<Millimetres> m = read_marker_csv(file_bytes(corpus_data() / "good/hand.csv"), "hand.csv");
  EXPECT_EQ(m.labels, (std::vector<std::string>{"2.1", "HEAD_L"}));
  EXPECT_EQ(m.frame_rate_hz, 100.0);
  EXPECT_EQ(m.first_frame, 10);
  EXPECT_EQ(m.at(0, 2), Eigen::Vector3d(1.75, -21, 33.5));
  EXPECT_FALSE(m.present(1, 1));
}

TEST(MarkerCsv, DerivesTheRateFromTimesWithoutASetting) {
  const MarkerFrames<Millimetres> m = read_marker_csv("frame,time_s,A.x,A.y,A.z\n1,0,1,2,3\n2,0.25,1,2,3\n3,0.5,1,2,3\n", "t.csv");
  EXPECT_EQ(m.frame_rate_hz, 4.0);
}

enum class TextFormat { trc, csv };

class MarkerTextRoundTrip : public ::testing::TestWithParam<TextFormat> {};

TEST_P(MarkerTextRoundTrip, AgreesWithC3dOnRandomSets) {
  const std::uint64_t seed = test::test_seed(test::kCorpusSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  for (int round = 0; round < 10; ++round) {
    MarkerFrames<Millimetres> m = test::random_markers(rng, static_cast<Eigen::Index>(rng() % 30),
                                       static_cast<Eigen::Index>(rng() % 12));
    m.first_frame = static_cast<std::int64_t>(1 + rng() % 3);
    const MarkerFrames<Millimetres> back = GetParam() == TextFormat::trc ? read_trc(write_trc(m), "r.trc")
                                                         : read_marker_csv(write_marker_csv(m), "r.csv");
    if (GetParam() == TextFormat::csv && m.frame_count() > 0) {
      ASSERT_EQ(back, m);  // an empty CSV cannot say its first frame number
    }
    MarkerFrames<Millimetres> numbered = back;
    numbered.first_frame = m.first_frame;
    ASSERT_EQ(numbered, m);  // positions, NaN where missing, labels, rate
    // The same markers through C3D give the same positions (first frame aside: C3D writes 1).
    MarkerFrames<Millimetres> via_c3d = read_c3d(write_c3d(m), "r.c3d").markers;
    via_c3d.first_frame = m.first_frame;
    EXPECT_EQ(via_c3d, m);
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, MarkerTextRoundTrip, ::testing::Values(TextFormat::trc, TextFormat::csv),
                         [](const auto& info) { return info.param == TextFormat::trc ? "trc" : "csv"; });

TEST(Trc, WriterRoundTripKeepsFirstFrameAndRate) {
  std::mt19937_64 rng(3);
  MarkerFrames<Millimetres> m = test::random_markers(rng, 5, 2);
  m.first_frame = 7;
  m.frame_rate_hz = 120;
  EXPECT_EQ(read_trc(write_trc(m), "r.trc"), m);
}

}  // namespace
}  // namespace fapcast
