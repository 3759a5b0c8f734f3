// Resampling marker takes onto the voice build's 60 fps grid (marker_resample.hpp).
#include "fapcast/capture/marker_resample.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace fapcast {
namespace {

// Two markers moving linearly in time (mm = a + b t), at `rate` Hz for `frames` frames.
MarkerFrames<Millimetres> linear_take(double rate, Eigen::Index frames) {
  MarkerFrames<Millimetres> set = MarkerFrames<Millimetres>::zeros(2, frames);
  set.labels = {"8.1", "H.forehead"};
  set.frame_rate_hz = rate;
  for (Eigen::Index f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / rate;
    set.set(0, f, {1 + 30 * t, -2 - 7 * t, 100 + 0.5 * t});
    set.set(1, f, {-50 + 3 * t, 8, 90 - t});
  }
  return set;
}

TEST(MarkerResample, LinearMotionAt100And120And59_94FpsLandsOnTheLineAt60) {
  for (const double rate : {100.0, 120.0, 240.0, 59.94, 50.0}) {
    const MarkerFrames<Millimetres> in = linear_take(rate, 211);
    const MarkerFrames<Millimetres> out = resample_markers(in, 60);
    const double span_s = 210 / rate;
    EXPECT_EQ(out.frame_count(), static_cast<Eigen::Index>(std::floor(span_s * 60 + 1e-9)) + 1) << rate;
    EXPECT_EQ(out.frame_rate_hz, 60);
    EXPECT_EQ(out.labels, in.labels);
    const MarkerFrames<Millimetres> want = linear_take(60, out.frame_count());
    EXPECT_LT((out.positions - want.positions).cwiseAbs().maxCoeff(), 1e-9) << rate;
    EXPECT_FALSE(out.positions.hasNaN());
  }
}

TEST(MarkerResample, WholeMultiplesCopySamplesBitForBit) {
  MarkerFrames<Millimetres> in = linear_take(120, 9);
  in.positions(0, 4) = 1.0 / 3.0;  // not on the line: a copy must keep it
  const MarkerFrames<Millimetres> out = resample_markers(in, 60);
  ASSERT_EQ(out.frame_count(), 5);
  for (Eigen::Index k = 0; k < 5; ++k) EXPECT_TRUE((out.positions.col(k).array() == in.positions.col(2 * k).array()).all()) << k;
  EXPECT_EQ(resample_markers(linear_take(60, 7), 60), linear_take(60, 7));
}

TEST(MarkerResample, AMissingNeighbourMakesTheSampleMissing) {
  MarkerFrames<Millimetres> in = linear_take(100, 11);  // 0 .. 0.1 s -> 60 fps frames at 0, 1/60 ... 6/60
  in.drop(0, 3);  // t = 0.03: neighbour of 60 fps frame 2 (t = 0.0333)
  in.drop(1, 6);  // t = 0.06: neighbour of 60 fps frame 4 (source 6.67)
  const MarkerFrames<Millimetres> out = resample_markers(in, 60);
  ASSERT_EQ(out.frame_count(), 7);
  for (Eigen::Index k = 0; k < 7; ++k) {
    EXPECT_EQ(out.present(0, k), k != 2) << k;  // source 3.33: frames 3 and 4
    EXPECT_EQ(out.present(1, k), k != 4) << k;  // frame 3 is source 5 exactly: copied, present
  }
}

TEST(MarkerResample, EdgeCasesAndRefusals) {
  EXPECT_EQ(resample_markers(linear_take(100, 0), 60).frame_count(), 0);
  EXPECT_EQ(resample_markers(linear_take(100, 1), 60).frame_count(), 1);
  EXPECT_EQ(resample_markers(linear_take(30, 4), 60).frame_count(), 7);  // upsampling works too
  EXPECT_THROW((void)resample_markers(linear_take(100, 3), 0), std::invalid_argument);
  MarkerFrames<Millimetres> bad = linear_take(100, 3);
  bad.frame_rate_hz = -1;
  EXPECT_THROW((void)resample_markers(bad, 60), std::invalid_argument);
  bad.frame_rate_hz = std::nan("");
  EXPECT_THROW((void)resample_markers(bad, 60), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
