// PCA frames -> FAPs: a known displacement gives the right value and sign; a random round trip
// through a SYNTHETIC basis whose components are FAP displacement patterns recovers the FAPs.
#include "fapcast/codec/pca_faps.hpp"

#include "fapcast/codec/face_geometry.hpp"
#include "fapcast/codec/fap_axis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace fapcast {
namespace {

// A "mesh" whose vertices are the generic face's feature points, in map order.
struct PointMesh {
  std::vector<FeaturePointVertex> points;
  RowMajorMatrixXf neutral;  // 1 x 3N
  FeaturePointPositions positions;
};

PointMesh point_mesh() {
  PointMesh m;
  m.positions = generic_adult_face().feature_points;
  m.neutral.resize(1, 3 * static_cast<Eigen::Index>(m.positions.size()));
  std::int64_t v = 0;
  for (const auto& [fp, at] : m.positions) {
    m.points.push_back({fp, v});
    for (int a = 0; a < 3; ++a) m.neutral(0, 3 * v + a) = static_cast<float>(at(a));
    ++v;
  }
  return m;
}

Eigen::Index column_of(const PointMesh& m, FeaturePoint fp) {
  for (const auto& p : m.points)
    if (p.fp == fp) return 3 * static_cast<Eigen::Index>(p.vertex);
  throw std::logic_error("no point " + fp.label());
}

TEST(PcaFaps, KnownDisplacementsGiveValueAndSign) {
  const PointMesh m = point_mesh();
  const FapuValues fapu = measure_fapu(m.positions);
  // Component 0: chin 0.5 cm down, lower lip 2.3 with it and 0.1 cm more, so open_jaw > 0 and
  // raise_b_midlip < 0 (relative to the jaw). Component 1: left outer corner 8.3 0.2 cm to the
  // face's left (+x), right corner 8.4 0.2 cm to its right (-x): both stretch (> 0).
  // Component 2: chin 0.1 cm forward and 0.05 cm to the face's right: thrust and shift > 0.
  RowMajorMatrixXf comp = RowMajorMatrixXf::Zero(3, m.neutral.cols());
  comp(0, column_of(m, {2, 1}) + 1) = -0.5f;
  comp(0, column_of(m, {2, 3}) + 1) = -0.6f;
  comp(1, column_of(m, {8, 3}) + 0) = 0.2f;
  comp(1, column_of(m, {8, 4}) + 0) = -0.2f;
  comp(2, column_of(m, {2, 1}) + 2) = 0.1f;
  comp(2, column_of(m, {2, 1}) + 0) = -0.05f;
  const FeaturePointBasis basis = restrict_basis(m.neutral, comp, m.points, m.positions);
  Eigen::MatrixXf c(2, 3);
  c << 1, 1, 1, 0, 0, 0;
  const auto frames = pca_to_faps(c, basis);
  ASSERT_EQ(frames.size(), 2u);
  const FapFrame& f = frames[0];
  EXPECT_EQ(f.value(3), std::lround(0.5 / fapu.mns)) << "open_jaw: chin down";
  EXPECT_EQ(f.value(5), std::lround(-0.1 / fapu.mns)) << "raise_b_midlip: 1 mm below the jaw";
  EXPECT_EQ(f.value(53), std::lround(0.2 / fapu.mw)) << "stretch_l_cornerlip_o";
  EXPECT_EQ(f.value(54), std::lround(0.2 / fapu.mw)) << "stretch_r_cornerlip_o";
  EXPECT_EQ(f.value(14), std::lround(0.1 / fapu.mns)) << "thrust_jaw";
  EXPECT_EQ(f.value(15), std::lround(0.05 / fapu.mw)) << "shift_jaw to the right";
  EXPECT_EQ(f.value(4), 0) << "upper lip did not move";
  EXPECT_GT(f.value(3), 0);
  EXPECT_LT(f.value(5), 0);
  for (int fap = 3; fap <= kFapCount; ++fap) EXPECT_EQ(frames[1].value(fap), 0) << "neutral frame, FAP " << fap;
  EXPECT_TRUE(f.mask.test(3) && f.mask.test(14) && f.mask.test(15) && f.mask.test(5) && f.mask.test(53));
  EXPECT_FALSE(f.mask.test(1) || f.mask.test(47) || f.mask.test(48) || f.mask.test(29));
  EXPECT_EQ(f.mask, drivable_faps(basis));

  PcaFapOptions absolute;
  absolute.jaw_relative = false;
  EXPECT_EQ(pca_to_faps(c, basis, absolute)[0].value(5), std::lround(-0.6 / fapu.mns));
}

TEST(PcaFaps, MeanAwayFromNeutralIsADisplacementToo) {
  const PointMesh m = point_mesh();
  RowMajorMatrixXf mean = m.neutral;
  mean(0, column_of(m, {2, 2}) + 1) -= 0.22f;  // upper lip 2.2 mm lower than at rest
  const FeaturePointBasis basis = restrict_basis(mean, RowMajorMatrixXf::Zero(1, mean.cols()), m.points, m.positions);
  const auto f = pca_to_faps(Eigen::MatrixXf::Zero(1, 1), basis)[0];
  EXPECT_EQ(f.value(4), std::lround(0.22 / measure_fapu(m.positions).mns));  // lower_t_midlip: down
}

// A basis whose component i moves FAP faps[i]'s point by 100 units along its axis; a jaw-borne
// point also follows the chin's components, as a player would move it.
struct FapPatternBasis {
  std::vector<int> faps;
  FeaturePointBasis basis;
};

FapPatternBasis fap_pattern_basis() {
  const PointMesh m = point_mesh();
  const FapuValues fapu = measure_fapu(m.positions);
  const FeaturePointBasis probe = restrict_basis(m.neutral, RowMajorMatrixXf::Zero(1, m.neutral.cols()), m.points, m.positions);
  const FapMask mask = drivable_faps(probe);
  std::vector<int> faps;
  for (int fap = 3; fap <= kFapCount; ++fap)
    if (mask.test(fap)) faps.push_back(fap);
  RowMajorMatrixXf comp = RowMajorMatrixXf::Zero(static_cast<Eigen::Index>(faps.size()), m.neutral.cols());
  for (std::size_t i = 0; i < faps.size(); ++i) {
    const FapInfo& info = fap_info(faps[i]);
    const Eigen::Vector3d step = *fap_axis(faps[i]) * fapu.of(info.unit) * 100.0;
    auto move = [&](FeaturePoint fp) {
      for (int a = 0; a < 3; ++a) comp(static_cast<Eigen::Index>(i), column_of(m, fp) + a) += static_cast<float>(step(a));
    };
    move(*info.feature_point);
    if (*info.feature_point == FeaturePoint{2, 1})
      for (const auto& p : m.points)
        if (is_jaw_borne(p.fp)) move(p.fp);
  }
  return {faps, restrict_basis(m.neutral, comp, m.points, m.positions)};
}

TEST(PcaFaps, RandomRoundTripThroughFapPatterns) {
  const auto [faps, basis] = fap_pattern_basis();
  ASSERT_GE(faps.size(), 30u);
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> value(-400, 400);
  Eigen::MatrixXf c(50, static_cast<Eigen::Index>(faps.size()));
  std::vector<std::vector<int>> want(50);
  for (Eigen::Index n = 0; n < 50; ++n)
    for (std::size_t i = 0; i < faps.size(); ++i) {
      want[static_cast<std::size_t>(n)].push_back(value(rng));
      c(n, static_cast<Eigen::Index>(i)) = static_cast<float>(want[static_cast<std::size_t>(n)].back()) / 100.0f;
    }
  const auto frames = pca_to_faps(c, basis);
  for (std::size_t n = 0; n < 50; ++n)
    for (std::size_t i = 0; i < faps.size(); ++i)
      ASSERT_NEAR(frames[n].value(faps[i]), want[n][i], 1) << "frame " << n << " FAP " << faps[i];
}

// A long track is converted a block of frames at a time: every frame, on both sides of each
// block's edge, is what it is converted alone.
TEST(PcaFaps, LongTrackEqualsFrameByFrame) {
  const auto [faps, basis] = fap_pattern_basis();
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<float> value(-4.0f, 4.0f);
  const Eigen::Index rows = 2 * 4096 + 7;
  Eigen::MatrixXf c(rows, static_cast<Eigen::Index>(faps.size()));
  for (Eigen::Index n = 0; n < rows; ++n)
    for (Eigen::Index i = 0; i < c.cols(); ++i) c(n, i) = value(rng);
  const auto frames = pca_to_faps(c, basis);
  ASSERT_EQ(frames.size(), static_cast<std::size_t>(rows));
  for (const Eigen::Index n : {Eigen::Index{0}, Eigen::Index{4095}, Eigen::Index{4096}, Eigen::Index{8191},
                               Eigen::Index{8192}, rows - 1}) {
    const auto alone = pca_to_faps(Eigen::MatrixXf(c.row(n)), basis);
    ASSERT_EQ(alone.size(), 1u);
    EXPECT_EQ(frames[static_cast<std::size_t>(n)].values, alone[0].values) << "frame " << n;
    EXPECT_EQ(frames[static_cast<std::size_t>(n)].mask, alone[0].mask) << "frame " << n;
  }
}

// The values are rounded two at a time; a value outside int32 (or NaN) takes the slow path
// without disturbing the FAP next to it.
TEST(PcaFaps, SaturationStaysInItsOwnFap) {
  const auto [faps, basis] = fap_pattern_basis();
  const auto k = static_cast<Eigen::Index>(faps.size());
  Eigen::MatrixXf c(2 + k, k);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> value(-4.0f, 4.0f);
  for (Eigen::Index i = 0; i < k; ++i) c(0, i) = value(rng);
  c.row(1) = c.row(0);
  c(1, 0) = std::numeric_limits<float>::quiet_NaN();
  for (Eigen::Index j = 0; j < k; ++j) {
    c.row(2 + j) = c.row(0);
    c(2 + j, j) = j % 2 ? 1e30f : -1e30f;
  }
  const auto frames = pca_to_faps(c, basis);
  constexpr auto kMax = std::numeric_limits<std::int32_t>::max(), kMin = std::numeric_limits<std::int32_t>::min();
  for (const int fap : faps) EXPECT_EQ(frames[1].value(fap), kMin) << "NaN reaches every FAP: FAP " << fap;
  for (Eigen::Index j = 0; j < k; ++j) {
    const auto& f = frames[static_cast<std::size_t>(2 + j)];
    EXPECT_EQ(f.value(faps[static_cast<std::size_t>(j)]), j % 2 ? kMax : kMin) << "FAP " << faps[static_cast<std::size_t>(j)];
    int unchanged = 0;
    for (const int fap : faps) {
      const std::int32_t v = f.value(fap);
      EXPECT_TRUE(v == frames[0].value(fap) || v == kMax || v == kMin) << "FAP " << fap;
      unchanged += v == frames[0].value(fap);
    }
    // Only FAPs on the same point along the same axis, or jaw-borne ones for the chin, follow.
    EXPECT_GE(unchanged, static_cast<int>(faps.size()) - 12) << "component " << j;
  }
}

TEST(PcaFaps, RefusesBadBases) {
  const PointMesh m = point_mesh();
  const RowMajorMatrixXf comp = RowMajorMatrixXf::Zero(2, m.neutral.cols());
  auto pts = m.points;
  pts[0].vertex = 1'000'000;
  EXPECT_THROW(restrict_basis(m.neutral, comp, pts, m.positions), std::invalid_argument);
  pts = m.points;
  pts.push_back(pts[0]);
  EXPECT_THROW(restrict_basis(m.neutral, comp, pts, m.positions), std::invalid_argument);
  EXPECT_THROW(restrict_basis(m.neutral, RowMajorMatrixXf::Zero(2, 9), m.points, m.positions), std::invalid_argument);
  FeaturePointPositions missing = m.positions;
  missing.erase({2, 1});
  EXPECT_THROW(restrict_basis(m.neutral, comp, m.points, missing), std::invalid_argument);
  const auto basis = restrict_basis(m.neutral, comp, m.points, m.positions);
  EXPECT_THROW(pca_to_faps(Eigen::MatrixXf::Zero(1, 3), basis), std::invalid_argument);
}

TEST(PcaFaps, ToFapValueRoundsAndSaturates) {
  const FapuValues fapu = measure_fapu(generic_adult_face().feature_points);
  EXPECT_EQ(to_fap_value(3, 1.5 * fapu.mns, fapu), 2);
  EXPECT_EQ(to_fap_value(3, -1.5 * fapu.mns, fapu), -2);
  EXPECT_EQ(to_fap_value(47, 0.1, fapu), 10000);  // tongue_roll: 0.1 rad in AU
  EXPECT_EQ(to_fap_value(3, 1e30, fapu), std::numeric_limits<std::int32_t>::max());
  EXPECT_EQ(to_fap_value(3, -1e30, fapu), std::numeric_limits<std::int32_t>::min());
  EXPECT_EQ(to_fap_value(3, std::numeric_limits<double>::quiet_NaN(), fapu), std::numeric_limits<std::int32_t>::min());
}

// Rounding without libm is std::round exactly: halves, their neighbours, the int32 edges.
TEST(PcaFaps, ToFapValueIsStdRoundSaturated) {
  const FapuValues fapu = measure_fapu(generic_adult_face().feature_points);
  const double unit = fapu.of(fap_info(3).unit);
  auto expected = [&](double amount) -> std::int32_t {
    const double v = std::round(amount / unit);
    if (!(v >= std::numeric_limits<std::int32_t>::min())) return std::numeric_limits<std::int32_t>::min();
    if (v > std::numeric_limits<std::int32_t>::max()) return std::numeric_limits<std::int32_t>::max();
    return static_cast<std::int32_t>(v);
  };
  std::vector<double> units{0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 1e6 + 0.5, -1e6 - 0.5,
                            2147483647.0, 2147483647.4, 2147483647.5, 2147483648.0, -2147483648.0,
                            -2147483648.4, -2147483648.5, -2147483649.0, 1e300, -1e300};
  for (double h = 0.5; h < 1e9; h = h * 3 + 0.5) {
    units.push_back(h);
    units.push_back(std::nextafter(h, 0.0));
    units.push_back(std::nextafter(h, 1e18));
    units.push_back(-std::nextafter(h, 0.0));
  }
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> any(-3e9, 3e9);
  for (int i = 0; i < 10000; ++i) units.push_back(any(rng));
  for (const double x : units) {
    const double amount = x * unit;
    EXPECT_EQ(to_fap_value(3, amount, fapu), expected(amount)) << "amount " << amount << " (" << x << " units)";
  }
}

}  // namespace
}  // namespace fapcast
