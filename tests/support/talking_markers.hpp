#pragma once
// A small known generator of "speech-like" data for the voice-math tests and benchmark: a 3-D
// articulation (jaw opening, lip rounding, lip spreading) moving smoothly in time drives p source
// markers and N target vertices through fixed smooth non-linear maps. It is SYNTHETIC test data,
// not the reference talker: its only job is to give the RBF and PCA code data whose truth is known.
#include "support/test_seed.hpp"

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace fapcast::test {

// The default seed of the voice-math tests (support/test_seed.hpp).
inline constexpr std::uint64_t kTalkingMarkerSeed = 20261122;

// 3 x n articulation trajectory in [-1, 1]^3: sums of slow sines with random phases.
inline Eigen::MatrixXd articulation(Eigen::Index n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> phase(0.0, 6.283185307179586);
  std::uniform_real_distribution<double> rate(0.01, 0.09);  // radians per frame at 60 fps
  Eigen::MatrixXd a(3, n);
  for (int c = 0; c < 3; ++c) {
    const double p1 = phase(rng), p2 = phase(rng), w1 = rate(rng), w2 = rate(rng) * 0.37;
    for (Eigen::Index t = 0; t < n; ++t) {
      a(c, t) = 0.7 * std::sin(w1 * static_cast<double>(t) + p1) +
                0.3 * std::sin(w2 * static_cast<double>(t) + p2);
    }
  }
  return a;
}

// A fixed smooth non-linear map from articulation (3 x n) to `rows` coordinates (rows x n):
// base + linear + quadratic + sinusoidal terms with random (seeded) coefficients, scaled to
// centimetre-sized motion around decimetre-sized coordinates (metres).
inline Eigen::MatrixXd smooth_shape_map(const Eigen::MatrixXd& a, Eigen::Index rows,
                                        std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  auto random = [&](Eigen::Index r, Eigen::Index c) {
    Eigen::MatrixXd m(r, c);
    for (Eigen::Index j = 0; j < c; ++j)
      for (Eigen::Index i = 0; i < r; ++i) m(i, j) = normal(rng);
    return m;
  };
  const Eigen::VectorXd base = 0.1 * random(rows, 1);
  const Eigen::MatrixXd linear = 0.01 * random(rows, 3);
  const Eigen::MatrixXd quadratic = 0.004 * random(rows, 6);
  // 12 waves: with 3 linear and 6 quadratic terms the map has 21 features, so 21 prototypes of
  // it span a full 20-dimensional centred space (as the ICT shape recipes do).
  const Eigen::MatrixXd wave = 0.003 * random(rows, 12);
  Eigen::MatrixXd features(6, a.cols()), waves(12, a.cols());
  for (Eigen::Index t = 0; t < a.cols(); ++t) {
    const double x = a(0, t), y = a(1, t), z = a(2, t);
    features.col(t) << x * x, y * y, z * z, x * y, y * z, x * z;
    for (int w = 0; w < 4; ++w) {
      const double f = 1.5 + 0.5 * w;
      waves(3 * w, t) = std::sin(f * x + w);
      waves(3 * w + 1, t) = std::sin(f * y - 0.5 * w);
      waves(3 * w + 2, t) = std::cos(f * z + x);
    }
  }
  Eigen::MatrixXd out = linear * a + quadratic * features + wave * waves;
  out.colwise() += base;
  return out;
}

// Indices of `count` frames spread out by farthest-point sampling (starting from frame 0): the
// test's stand-in for prototype selection.
inline std::vector<Eigen::Index> spread_frames(const Eigen::MatrixXd& frames, int count) {
  std::vector<Eigen::Index> picked{0};
  Eigen::VectorXd nearest = (frames.colwise() - frames.col(0)).colwise().squaredNorm().transpose();
  while (static_cast<int>(picked.size()) < count) {
    Eigen::Index next = 0;
    nearest.maxCoeff(&next);
    picked.push_back(next);
    nearest = nearest.cwiseMin((frames.colwise() - frames.col(next)).colwise().squaredNorm().transpose());
  }
  return picked;
}

// Rows `picked` of the columns of `frames`: m x rows.
inline Eigen::MatrixXd as_rows(const Eigen::MatrixXd& frames, const std::vector<Eigen::Index>& picked) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(picked.size()), frames.rows());
  for (std::size_t i = 0; i < picked.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = frames.col(picked[i]).transpose();
  return out;
}

}  // namespace fapcast::test
