#include "fapcast/talker/capture_imperfections.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/test_timeline.hpp"

namespace fapcast {
namespace {

// mt19937_64's sequence is fixed by the standard: its 10000th output from the default seed.
TEST(PortableRandom, EngineIsTheStandardMersenneTwister) {
  std::mt19937_64 engine;
  engine.discard(9999);
  EXPECT_EQ(engine(), 9981545732273789042ull);
}

TEST(PortableRandom, DistributionsHaveTheirMomentsAndRepeat) {
  PortableRandom a(7), b(7);
  double sum = 0, squares = 0, low = 1, high = 0;
  constexpr int kN = 200000;
  for (int i = 0; i < kN; ++i) {
    const double x = a.normal();
    EXPECT_EQ(x, b.normal());
    sum += x;
    squares += x * x;
    const double u = a.uniform();
    (void)b.uniform();
    low = std::min(low, u);
    high = std::max(high, u);
  }
  EXPECT_NEAR(sum / kN, 0.0, 0.01);
  EXPECT_NEAR(squares / kN, 1.0, 0.01);
  EXPECT_GE(low, 0.0);
  EXPECT_LT(high, 1.0);
  PortableRandom c(1);
  for (int i = 0; i < 1000; ++i) EXPECT_LT(c.below(7), 7u);
  // Golden first draws: the same on every standard library (portable distributions).
  PortableRandom g(42);
  EXPECT_DOUBLE_EQ(g.uniform(), static_cast<double>(std::mt19937_64(42)() >> 11) * 0x1.0p-53);
}

MarkerFrames<Centimetres> still_take(Eigen::Index markers, Eigen::Index frames) {
  MarkerFrames<Centimetres> take;
  take.labels.assign(static_cast<std::size_t>(markers), "m");
  take.positions = Eigen::MatrixXd::Zero(3 * markers, frames);
  for (Eigen::Index m = 0; m < markers; ++m)
    take.positions.middleRows(3 * m, 3).colwise() = Eigen::Vector3d(m % 5 - 2.0, m / 5 - 2.0, 10.0);
  return take;
}

TEST(CaptureImperfections, MarkerNoiseHasTheStatedSigma) {
  MarkerFrames<Centimetres> take = still_take(20, 600);
  const MarkerFrames<Centimetres> clean = take;
  PortableRandom random(test::test_seed(test::kTimelineSeed));
  add_marker_noise(take, random, 0.2);
  const Eigen::MatrixXd e = (take.positions - clean.positions) * 10.0;  // mm
  const double sigma = std::sqrt(e.squaredNorm() / static_cast<double>(e.size()));
  EXPECT_NEAR(sigma, 0.2, 0.01);
  EXPECT_NEAR(e.mean(), 0.0, 0.01);
}

// Head motion stays within its limits and is smooth (no frame-to-frame jumps).
TEST(CaptureImperfections, HeadMotionIsSmallAndSmooth) {
  PortableRandom random(test::test_seed(test::kTimelineSeed));
  for (int take = 0; take < 20; ++take) {
    const HeadMotion motion(random, {3.0, 3.0, {0.0, -12.0, 0.0}});
    RigidTransform previous = motion.at(0.0);
    for (int k = 0; k < 600; ++k) {
      const RigidTransform pose = motion.at(k / 60.0);
      const double angle = Eigen::AngleAxisd(pose.rotation).angle() * 180.0 / std::numbers::pi;
      EXPECT_LE(angle, 3.0 * std::sqrt(3.0));
      // The pivot moves only by the translation, at most 3 mm per axis.
      const Eigen::Vector3d pivot(0.0, -12.0, 0.0);
      EXPECT_LE((pose.apply(pivot) - pivot).cwiseAbs().maxCoeff(), 0.3 + 1e-12);
      const Eigen::Vector3d lip(0.0, -3.3, 11.3);
      // Speed bound: each axis moves at most 2 pi 0.6 Hz x its peak; angular speed adds over
      // three axes, times the lever arm from the pivot to the lip.
      const double omega = std::sqrt(3.0) * 2 * std::numbers::pi * 0.6 * 3.0 * std::numbers::pi / 180.0;
      const double speed = omega * (lip - pivot).norm() + std::sqrt(3.0) * 2 * std::numbers::pi * 0.6 * 0.3;
      EXPECT_LT((pose.apply(lip) - previous.apply(lip)).norm(), speed / 60.0 * 1.01);
      previous = pose;
    }
  }
}

TEST(CaptureImperfections, DroppedRunsAreMissingAndWithinLimits) {
  MarkerFrames<Centimetres> take = still_take(30, 3600);  // one minute
  PortableRandom random(test::test_seed(test::kTimelineSeed));
  const auto runs = drop_marker_runs(take, random, {3.0, 24});
  // Expected 90 runs (30 markers x 3 per minute); Poisson spread.
  EXPECT_GT(runs.size(), 50u);
  EXPECT_LT(runs.size(), 140u);
  Eigen::Index missing = 0;
  for (Eigen::Index m = 0; m < take.marker_count(); ++m)
    for (Eigen::Index k = 0; k < take.frame_count(); ++k) missing += take.present(m, k) ? 0 : 1;
  Eigen::Index dropped = 0;
  for (const auto& run : runs) {
    EXPECT_GE(run.frame_count, 1);
    EXPECT_LE(run.frame_count, 24);
    for (Eigen::Index k = run.first_frame; k < run.first_frame + run.frame_count; ++k)
      EXPECT_FALSE(take.present(run.marker, k));
    dropped += run.frame_count;
  }
  EXPECT_EQ(missing, dropped);  // runs never overlap
}

TEST(CaptureImperfections, SameSeedSameTakeOtherSeedOtherTake) {
  const auto make = [](std::uint64_t seed) {
    PortableRandom random(seed);
    MarkerFrames<Centimetres> take = still_take(10, 300);
    apply_head_motion(take, HeadMotion(random));
    add_marker_noise(take, random);
    drop_marker_runs(take, random, {20.0, 10});
    return take;
  };
  const MarkerFrames<Centimetres> a = make(5), b = make(5), c = make(6);
  EXPECT_TRUE(a.positions.cwiseEqual(b.positions).count() +
                  (a.positions.array().isNaN() && b.positions.array().isNaN()).count() ==
              a.positions.size());
  EXPECT_FALSE(a.positions.isApprox(c.positions));
}

TEST(CaptureImperfections, UtteranceVariationStaysInRange) {
  PortableRandom random(test::test_seed(test::kTimelineSeed));
  for (int i = 0; i < 1000; ++i) {
    const auto v = draw_utterance_variation(random);
    EXPECT_GE(v.rate_factor, 0.88);
    EXPECT_LT(v.rate_factor, 1.12);
    EXPECT_GE(v.effort, 0.85f);
    EXPECT_LE(v.effort, 1.15f);
  }
}

}  // namespace
}  // namespace fapcast
