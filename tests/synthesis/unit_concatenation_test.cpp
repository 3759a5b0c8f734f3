// Time warping, join cross-fades and the smoothing spline: properties, not printed numbers.
#include "fapcast/synthesis/unit_concatenation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

namespace fapcast {
namespace {

// Largest |second difference| of column 0 over frames [lo, hi).
float max_second_difference(const Eigen::MatrixXf& y, Eigen::Index lo, Eigen::Index hi) {
  float m = 0;
  for (Eigen::Index n = std::max<Eigen::Index>(lo, 1); n + 1 < std::min(hi, y.rows()); ++n)
    m = std::max(m, std::abs(y(n + 1, 0) - 2 * y(n, 0) + y(n - 1, 0)));
  return m;
}

TEST(SmoothTrajectory, KeepsStraightLinesAndTheMean) {
  Eigen::MatrixXf line(50, 2);
  for (int n = 0; n < 50; ++n) line.row(n) << 3.0f * n - 7, -0.5f * n;
  const std::vector<double> ones(50, 1.0);
  EXPECT_LT((smooth_trajectory(line, ones, 100.0) - line).cwiseAbs().maxCoeff(), 1e-3f);

  std::mt19937_64 rng(7);
  std::normal_distribution<float> noise;
  Eigen::MatrixXf x(200, 1);
  for (int n = 0; n < 200; ++n) x(n, 0) = noise(rng);
  const Eigen::MatrixXf y = smooth_trajectory(x, std::vector<double>(200, 1.0), 10.0);
  EXPECT_NEAR(y.sum(), x.sum(), 1e-2f) << "second differences cannot move the mean";
  EXPECT_LT(max_second_difference(y, 0, 200), 0.5f * max_second_difference(x, 0, 200));
  EXPECT_EQ(smooth_trajectory(x, std::vector<double>(200, 1.0), 0.0), x);
}

TEST(SmoothTrajectory, HeavyWeightsPinFrames) {
  Eigen::MatrixXf x = Eigen::MatrixXf::Zero(61, 1);
  x(30, 0) = -1.0f;  // a one-frame dip, like a lip closure at its deepest
  std::vector<double> w(61, 1.0);
  const float free_dip = smooth_trajectory(x, w, 5.0)(30, 0);
  w[30] = 1000.0;
  const float held_dip = smooth_trajectory(x, w, 5.0)(30, 0);
  EXPECT_GT(free_dip, -0.5f) << "unweighted smoothing flattens the dip";
  EXPECT_LT(held_dip, -0.95f) << "a held frame keeps its depth";
}

// One recording 0..(n-1) of k = 1 where the frame value equals its index.
struct Ramp {
  std::vector<PhoneState> states;
  Eigen::MatrixXf frames;
};

Ramp ramp(std::vector<std::uint32_t> phone_frames) {
  Ramp r;
  std::uint32_t f = 0;
  int v = 0;
  for (auto c : phone_frames) {
    r.states.push_back({0, static_cast<VisemeClass>(v++), {f, c}});
    f += c;
  }
  r.frames = Eigen::VectorXf::LinSpaced(f, 0.0f, static_cast<float>(f - 1));
  return r;
}

TEST(ConcatenateUnits, IdentityWarpReproducesTheRecording) {
  const Ramp r = ramp({4, 6, 5});
  const PhoneGraph g(r.states);
  SearchResult sel{{0, 1, 2}, {{0, 0, 3}}, 1.0, {}};
  const std::vector<TargetPhone> targets{{r.states[0].viseme, 10, 14}, {r.states[1].viseme, 14, 20}, {r.states[2].viseme, 20, 25}};
  const Eigen::MatrixXf y = concatenate_units(g, r.frames, sel, targets, {0, 0.0, 1.0});
  ASSERT_EQ(y.rows(), 15);
  EXPECT_LT((y - r.frames).cwiseAbs().maxCoeff(), 1e-5f);
}

TEST(ConcatenateUnits, WarpStretchesEachPhoneToItsTargetDuration) {
  const Ramp r = ramp({4, 4});
  const PhoneGraph g(r.states);
  SearchResult sel{{0, 1}, {{0, 0, 2}}, 1.0, {}};
  // Phone 0 (frames 0..3) stretched to 8 frames, phone 1 (4..7) squeezed to 2.
  const std::vector<TargetPhone> targets{{r.states[0].viseme, 0, 8}, {r.states[1].viseme, 8, 10}};
  const Eigen::MatrixXf y = concatenate_units(g, r.frames, sel, targets, {0, 0.0, 1.0});
  ASSERT_EQ(y.rows(), 10);
  for (int n = 1; n < 8; ++n) EXPECT_GE(y(n, 0), y(n - 1, 0)) << "monotone source stays monotone";
  EXPECT_NEAR(y(6, 0) - y(1, 0), 2.5f, 1e-4f) << "8 frames cover phone 0's span at half speed";
  EXPECT_NEAR(y(9, 0) - y(8, 0), 2.0f, 1e-4f) << "2 frames cover phone 1's span at double speed";
  EXPECT_THROW(concatenate_units(g, r.frames, sel, std::vector<TargetPhone>{{r.states[0].viseme, 0, 0}, {r.states[1].viseme, 0, 2}}),
               std::invalid_argument);
}

TEST(ConcatenateUnits, JoinsAreSmootherAfterCrossFadeAndSmoothing) {
  // Two recordings at different levels: joining them is a jump of 10.
  const auto a = static_cast<VisemeClass>(0), b = static_cast<VisemeClass>(1);
  std::vector<PhoneState> states{{0, a, {0, 10}}, {0, b, {10, 10}}, {1, a, {20, 10}}, {1, b, {30, 10}}};
  Eigen::MatrixXf frames(40, 1);
  for (int n = 0; n < 40; ++n) frames(n, 0) = n < 20 ? 0.0f : 10.0f;
  const PhoneGraph g(states);
  SearchResult sel{{0, 3}, {{0, 0, 1}, {3, 1, 1}}, 2.0, {}};
  const std::vector<TargetPhone> targets{{a, 0, 10}, {b, 10, 20}};
  const Eigen::MatrixXf raw = concatenate_units(g, frames, sel, targets, {0, 0.0, 1.0, false});
  const Eigen::MatrixXf smooth = concatenate_units(g, frames, sel, targets, {3, 2.0, 1.0, false});
  EXPECT_NEAR(max_second_difference(raw, 5, 15), 10.0f, 1e-4f);
  EXPECT_LT(max_second_difference(smooth, 5, 15), 2.5f);
  EXPECT_NEAR(smooth(0, 0), 0.0f, 0.2f);
  EXPECT_NEAR(smooth(19, 0), 10.0f, 0.2f);
  // Mid-phone (the default): the same jump, moved to the middle of the first phone, smoothed alike.
  const Eigen::MatrixXf mid_raw = concatenate_units(g, frames, sel, targets, {0, 0.0, 1.0, true});
  const Eigen::MatrixXf mid = concatenate_units(g, frames, sel, targets, {});
  EXPECT_NEAR(max_second_difference(mid_raw, 1, 9), 10.0f, 1e-4f);
  EXPECT_LT(max_second_difference(mid, 1, 9), 2.5f);
  EXPECT_NEAR(mid(19, 0), 10.0f, 0.2f);
}

// Where a unit takes over. Recording 1 holds "a b" at level 10, recording 0 "a b" at level 0,
// recording 2 "c b" at level 20. A join into recording 1's /b/ (whose parent is an /a/, like the
// phone left) hands over in the middle of target /a/, which then shows recording 1's /a/; into
// recording 2's /b/ (a hard join: its parent is a /c/) it stays at the boundary.
TEST(ConcatenateUnits, MidPhoneJoinHandsOverInThePhoneBefore) {
  const auto a = static_cast<VisemeClass>(0), b = static_cast<VisemeClass>(1), c = static_cast<VisemeClass>(2);
  std::vector<PhoneState> states{{0, a, {0, 10}}, {0, b, {10, 10}}, {1, a, {20, 8}},
                                 {1, b, {28, 10}}, {2, c, {38, 10}}, {2, b, {48, 10}}};
  Eigen::MatrixXf frames(58, 1);
  for (int n = 0; n < 58; ++n) frames(n, 0) = n < 20 ? 0.0f : n < 38 ? 10.0f : 20.0f;
  const PhoneGraph g(states);
  const std::vector<TargetPhone> targets{{a, 0, 9}, {b, 9, 20}};
  const ConcatenationOptions cut_mid{0, 0.0, 1.0, true}, cut_boundary{0, 0.0, 1.0, false};
  auto level = [](const Eigen::MatrixXf& y, int n) { return y(n, 0); };

  const SearchResult admissible{{0, 3}, {{0, 0, 1}, {3, 1, 1}}, 2.0, {}};
  const Eigen::MatrixXf mid = concatenate_units(g, frames, admissible, targets, cut_mid);
  for (int n = 0; n < 4; ++n) EXPECT_EQ(level(mid, n), 0.0f) << n;  // recording 0's /a/
  for (int n = 4; n < 20; ++n) EXPECT_EQ(level(mid, n), 10.0f) << n;  // recording 1's /a/ from 9 / 2
  const Eigen::MatrixXf boundary = concatenate_units(g, frames, admissible, targets, cut_boundary);
  for (int n = 0; n < 9; ++n) EXPECT_EQ(level(boundary, n), 0.0f) << n;
  for (int n = 9; n < 20; ++n) EXPECT_EQ(level(boundary, n), 10.0f) << n;

  const SearchResult hard{{0, 5}, {{0, 0, 1}, {5, 1, 1}}, 2.0, {}};
  const Eigen::MatrixXf hard_mid = concatenate_units(g, frames, hard, targets, cut_mid);
  for (int n = 0; n < 9; ++n) EXPECT_EQ(level(hard_mid, n), 0.0f) << n;  // never a /c/ for an /a/
  for (int n = 9; n < 20; ++n) EXPECT_EQ(level(hard_mid, n), 20.0f) << n;

  // With the cross-fade, the hand-over is a raised cosine centred where the cut is.
  const Eigen::MatrixXf faded = concatenate_units(g, frames, admissible, targets, {2, 0.0, 1.0, true});
  EXPECT_EQ(level(faded, 1), 0.0f);
  EXPECT_GT(level(faded, 3), 0.0f);
  EXPECT_LT(level(faded, 4), 10.0f);
  EXPECT_EQ(level(faded, 6), 10.0f);
}

// The concatenation smooths as it goes; the result must be the smoother applied to the raw one
// (the weights: 1, or the hold weight inside held phones), to the bit. Phones of one frame make
// neighbouring cross-fade windows overlap (the later join wins).
TEST(ConcatenateUnits, SmoothingAsItConcatenatesIsTheSmootherOfTheRawConcatenation) {
  std::mt19937_64 rng(23);
  std::uniform_int_distribution<std::uint32_t> length(1, 8);
  std::normal_distribution<float> noise;
  // Six recordings of five phones each, k = 3 random columns.
  std::vector<PhoneState> states;
  std::uint32_t f = 0;
  for (std::uint32_t u = 0; u < 6; ++u)
    for (int p = 0; p < 5; ++p) {
      const std::uint32_t c = length(rng);
      states.push_back({u, static_cast<VisemeClass>(p), {f, c}});
      f += c;
    }
  Eigen::MatrixXf frames(f, 3);
  for (Eigen::Index i = 0; i < frames.size(); ++i) frames.data()[i] = noise(rng);
  const PhoneGraph g(states);
  // 40 targets; a new unit (another recording, same phone position) every 1..4 targets.
  SearchResult sel;
  std::vector<TargetPhone> targets;
  std::vector<double> weights;
  std::int64_t at = 3;
  std::uniform_int_distribution<int> unit_length(1, 4), recording(0, 5);
  const ConcatenationOptions options{3, 2.0, 50.0};
  for (std::size_t t = 0; t < 40;) {
    const int len = unit_length(rng), rec = recording(rng);
    sel.units.push_back({static_cast<StateId>(rec * 5 + static_cast<int>(t % 5)), t, 0});
    for (int i = 0; i < len && t < 40; ++i, ++t) {
      const auto state = static_cast<StateId>(rec * 5 + static_cast<int>(t % 5));
      sel.states.push_back(state);
      ++sel.units.back().length;
      const std::int64_t n = length(rng);
      const bool hold = t % 7 == 3;
      targets.push_back({states[state].viseme, at, at + n, hold});
      weights.insert(weights.end(), static_cast<std::size_t>(n), hold ? options.hold_weight : 1.0);
      at += n;
    }
  }
  const Eigen::MatrixXf smooth = concatenate_units(g, frames, sel, targets, options);
  const Eigen::MatrixXf raw = concatenate_units(g, frames, sel, targets, {options.blend_half_width, 0.0, options.hold_weight});
  EXPECT_EQ(smooth, smooth_trajectory(raw, weights, options.smoothing));
  EXPECT_GT((smooth - raw).cwiseAbs().maxCoeff(), 0.01f) << "the smoother did something";
}

}  // namespace
}  // namespace fapcast
