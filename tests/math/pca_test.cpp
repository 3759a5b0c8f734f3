#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "fapcast/math/affine_image_pca.hpp"
#include "fapcast/math/em_pca.hpp"
#include "fapcast/math/pca_basis.hpp"
#include "fapcast/math/rbf_retarget.hpp"
#include "fapcast/math/running_moments.hpp"
#include "support/talking_markers.hpp"

namespace fapcast {
namespace {

// The realistic chain the voice build runs: a corpus of source marker frames, an RBF map fitted
// on 21 prototypes onto a D-dimensional target, and the retargeted frames streamed in chunks.
struct Retargeted {
  Eigen::MatrixXd sources;  // d x n
  RbfMap map;
  RunningCovariance responses;
};

Retargeted retarget(Eigen::Index frames, Eigen::Index target_dim, std::uint64_t seed) {
  const Eigen::MatrixXd a = test::articulation(frames, seed);
  Eigen::MatrixXd sources = test::smooth_shape_map(a, 60, seed + 1);
  const auto picked = test::spread_frames(a, 21);
  RunningSpread spread(60);
  for (Eigen::Index t = 0; t < frames; ++t) spread.add(sources.col(t));
  RbfMap map = fit_rbf_by_gcv(test::as_rows(sources, picked),
                              test::as_rows(test::smooth_shape_map(a, target_dim, seed + 2), picked),
                              spread.mean_squared_distance());
  RunningCovariance responses(21);
  for (Eigen::Index t = 0; t < frames; ++t) responses.add(map.responses(sources.col(t)));
  return {std::move(sources), std::move(map), std::move(responses)};
}

FrameStream stream_of(const Retargeted& r) {
  return {r.sources.cols(), r.map.target_dimension(),
          [&r](Eigen::Index first, Eigen::Ref<Eigen::MatrixXf> out) {
            r.map.map_columns(r.sources.middleCols(first, out.cols()), out);
          }};
}

TEST(PrincipalAngles, AreZeroForTheSameSpanAndRightForKnownRotations) {
  const Eigen::MatrixXd a = Eigen::MatrixXd::Identity(5, 2);
  Eigen::MatrixXd b = a * (Eigen::Matrix2d() << 2, 1, -1, 3).finished();
  EXPECT_LT(principal_angles(a, b).maxCoeff(), 1e-15);
  const double theta = 1e-7;  // tiny angles stay accurate (computed from sines)
  b.setZero();
  b(0, 0) = 1;
  b(1, 1) = std::cos(theta);
  b(2, 1) = std::sin(theta);
  const Eigen::VectorXd angles = principal_angles(a, b);
  EXPECT_NEAR(angles[0], 0.0, 1e-20);
  EXPECT_NEAR(angles[1], theta, 1e-20);
  b(1, 1) = 0;
  b(2, 1) = 1;
  EXPECT_NEAR(principal_angles(a, b)[1], M_PI / 2, 1e-15);
}

// Both routes of section 3.6 on a realistic-shaped problem: N = 1,000 vertices (D = 3,000),
// m = 21, 4,000 frames, k = 17 (kept small for the ASan run; the full ICT size is in
// tests/bench/voice_math_bench.cpp).
TEST(Pca, EmPcaAndTheExactRouteFindTheSameSubspace) {
  const std::uint64_t seed = test::test_seed(test::kTalkingMarkerSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  const Retargeted r = retarget(4000, 3000, seed);
  const PcaBasis exact = pca_of_affine_image(r.map.weights(), r.map.offset(), r.responses.mean(),
                                             r.responses.covariance(), 17);
  EmPcaOptions options;
  options.tolerance = 1e-4;
  const PcaBasis em = em_pca(stream_of(r), options);
  ASSERT_TRUE(em.converged) << em.iterations << " iterations";
  RecordProperty("em_iterations", em.iterations);

  const Eigen::VectorXd angles = principal_angles(exact.components, em.components);
  EXPECT_LT(angles.maxCoeff(), 1e-3) << angles.transpose();
  // Orthonormal components, the same means and variances.
  const Eigen::MatrixXd gram = em.components.transpose() * em.components;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(17, 17)).cwiseAbs().maxCoeff(), 1e-10);
  const Eigen::MatrixXd exact_gram = exact.components.transpose() * exact.components;
  EXPECT_LT((exact_gram - Eigen::MatrixXd::Identity(17, 17)).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((em.mean - exact.mean).norm(), 1e-5 * exact.mean.norm());
  for (int i = 0; i < 17; ++i) {
    EXPECT_NEAR(em.variances[i], exact.variances[i], 1e-3 * exact.variances[0]) << "component " << i;
  }
  EXPECT_NEAR(em.total_variance, exact.total_variance, 1e-4 * exact.total_variance);
  EXPECT_NEAR(em.explained_fraction(), exact.explained_fraction(), 1e-4);
  EXPECT_GT(exact.explained_fraction(), 0.99);
}

// The exact route against a brute-force eigen-decomposition of the frames' covariance, on a
// problem small enough to form it (D = 120).
TEST(Pca, ExactRouteMatchesTheDenseCovariance) {
  const std::uint64_t seed = test::test_seed(test::kTalkingMarkerSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  const Retargeted r = retarget(4000, 120, seed);
  Eigen::MatrixXd frames(120, 4000);
  for (Eigen::Index t = 0; t < 4000; ++t) frames.col(t) = r.map(r.sources.col(t));
  const Eigen::VectorXd mean = frames.rowwise().mean();
  const Eigen::MatrixXd centred = frames.colwise() - mean;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense(centred * centred.transpose() / 4000.0);
  const PcaBasis exact = pca_of_affine_image(r.map.weights(), r.map.offset(), r.responses.mean(),
                                             r.responses.covariance(), 8);
  const Eigen::MatrixXd top = dense.eigenvectors().rightCols(8);
  EXPECT_LT(principal_angles(top, exact.components).maxCoeff(), 1e-6);
  EXPECT_LT((exact.mean - mean).norm(), 1e-10 * mean.norm());
  EXPECT_NEAR(exact.total_variance, dense.eigenvalues().sum(), 1e-9 * exact.total_variance);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(exact.variances[i], dense.eigenvalues()[119 - i], 1e-9 * exact.variances[0]);
  }
  // Projection and reconstruction are each other's inverse on the subspace.
  const Eigen::VectorXd c = exact.project(frames.col(7));
  EXPECT_LT((exact.project(exact.reconstruct(c)) - c).norm(), 1e-12 * (c.norm() + 1));
}

TEST(Pca, EmPcaOnLowRankDataRecoversItExactlyAndRejectsBadOptions) {
  // Frames = mean + 3 known directions with distinct variances: EM-PCA with k = 3 finds them.
  const std::uint64_t seed = test::test_seed(test::kTalkingMarkerSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  const Eigen::MatrixXd dirs = orthonormal_basis(Eigen::MatrixXd::Random(50, 3));
  Eigen::MatrixXd frames(50, 999);
  for (Eigen::Index t = 0; t < 999; ++t) {
    frames.col(t) = Eigen::VectorXd::Constant(50, 1.0) + dirs * Eigen::Vector3d(3 * normal(rng), 2 * normal(rng), normal(rng));
  }
  const FrameStream stream{999, 50, [&](Eigen::Index first, Eigen::Ref<Eigen::MatrixXf> out) {
                             out = frames.middleCols(first, out.cols()).cast<float>();
                           }};
  EmPcaOptions options;
  options.components = 3;
  options.chunk_frames = 100;  // 999 frames: the last chunk is short
  const PcaBasis em = em_pca(stream, options);
  EXPECT_TRUE(em.converged);
  EXPECT_LT(principal_angles(dirs, em.components).maxCoeff(), 1e-4);
  EXPECT_NEAR(em.explained_fraction(), 1.0, 1e-6);
  EXPECT_GT(em.variances[0], em.variances[1]);
  EXPECT_GT(em.variances[1], em.variances[2]);
  options.components = 51;
  EXPECT_THROW(em_pca(stream, options), std::invalid_argument);
  EXPECT_THROW(em_pca(FrameStream{}, EmPcaOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
