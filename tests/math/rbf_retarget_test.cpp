#include "fapcast/math/rbf_retarget.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "fapcast/math/running_moments.hpp"
#include "support/talking_markers.hpp"

namespace fapcast {
namespace {

constexpr int kPrototypes = 21;

// A retargeting problem from the test generator: source markers (p = 20, d = 60) over a corpus,
// 21 spread-out prototype frames, and their target vectors (D = 90).
struct Problem {
  Eigen::MatrixXd corpus;   // d x n
  Eigen::MatrixXd centres;  // m x d
  Eigen::MatrixXd targets;  // m x D
  double r_squared = 0;
};

Problem make_problem(std::uint64_t seed, double scale = 1.0, Eigen::Index frames = 3000) {
  const Eigen::MatrixXd a = test::articulation(frames, seed);
  Problem p;
  p.corpus = scale * test::smooth_shape_map(a, 60, seed + 1);
  const auto picked = test::spread_frames(a, kPrototypes);
  p.centres = test::as_rows(p.corpus, picked);
  p.targets = test::as_rows(test::smooth_shape_map(a, 90, seed + 2), picked);
  RunningSpread spread(p.corpus.rows());
  for (Eigen::Index t = 0; t < p.corpus.cols(); ++t) spread.add(p.corpus.col(t));
  p.r_squared = spread.mean_squared_distance();
  return p;
}

Eigen::MatrixXd noise(Eigen::Index rows, Eigen::Index cols, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd e(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i) e(i, j) = normal(rng);
  return e;
}

class RbfInterpolation : public ::testing::TestWithParam<double> {};

// lambda -> 0 with distinct centres: the network reproduces every prototype (at any unit scale).
TEST_P(RbfInterpolation, ReproducesThePrototypesAsLambdaGoesToZero) {
  const std::uint64_t seed = test::test_seed(test::kTalkingMarkerSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  const Problem p = make_problem(seed, GetParam());
  const RbfRidgeProblem problem(p.centres, p.targets, p.r_squared);
  for (double lambda : {0.0, 1e-14 * problem.singular_values()[0] * problem.singular_values()[0]}) {
    const RbfMap map = problem.solve(lambda);
    double worst = 0;
    for (Eigen::Index k = 0; k < p.centres.rows(); ++k) {
      worst = std::max(worst, (map(p.centres.row(k).transpose()) - p.targets.row(k).transpose()).norm());
    }
    EXPECT_LT(worst, 1e-6 * p.targets.norm()) << "lambda " << lambda;
  }
  EXPECT_NEAR(problem.effective_parameters(0.0), kPrototypes, 1e-9);
}
INSTANTIATE_TEST_SUITE_P(Scales, RbfInterpolation, ::testing::Values(1e-4, 1.0, 1e4));

// The O(m) GCV formula equals GCV computed from an explicitly built hat matrix of the
// intercept + kernel design with the intercept unpenalised.
TEST(RbfGcv, MatchesTheExplicitHatMatrix) {
  const std::uint64_t seed = test::test_seed(test::kTalkingMarkerSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  const Problem p = make_problem(seed);
  const RbfRidgeProblem problem(p.centres, p.targets, p.r_squared);
  const Eigen::Index m = p.centres.rows();
  Eigen::MatrixXd a(m, m + 1);
  a << Eigen::VectorXd::Ones(m), problem.kernel();
  Eigen::MatrixXd penalty = Eigen::MatrixXd::Identity(m + 1, m + 1);
  penalty(0, 0) = 0;
  const double s2 = problem.singular_values()[0] * problem.singular_values()[0];
  for (double rel : {1e-6, 1e-3, 1e-1, 10.0}) {
    const double lambda = rel * s2;
    const Eigen::MatrixXd hat =
        a * (a.transpose() * a + lambda * penalty).ldlt().solve(a.transpose());
    const Eigen::MatrixXd residual = (Eigen::MatrixXd::Identity(m, m) - hat) * p.targets;
    const double tr = static_cast<double>(m) - hat.trace();
    const double explicit_gcv = static_cast<double>(m) * residual.squaredNorm() / (tr * tr);
    EXPECT_NEAR(problem.gcv(lambda), explicit_gcv, 1e-6 * explicit_gcv) << "lambda/s^2 " << rel;
    EXPECT_NEAR(problem.effective_parameters(lambda), hat.trace(), 1e-8);
    // The fitted map's values at the centres are the hat matrix applied to the targets.
    const RbfMap map = problem.solve(lambda);
    for (Eigen::Index k = 0; k < m; ++k) {
      EXPECT_LT((map(p.centres.row(k).transpose()) - (hat * p.targets).row(k).transpose()).norm(),
                1e-7 * p.targets.norm());
    }
  }
}

TEST(RbfGcv, ChosenLambdaIsTheMinimumOfTheCurve) {
  const std::uint64_t seed = test::test_seed(test::kTalkingMarkerSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  Problem p = make_problem(seed);
  p.targets += 2e-3 * noise(p.targets.rows(), p.targets.cols(), seed + 3);
  const RbfRidgeProblem problem(p.centres, p.targets, p.r_squared);
  const LambdaChoice choice = problem.choose_lambda();
  ASSERT_FALSE(choice.at_range_edge) << "lambda " << choice.lambda;
  EXPECT_DOUBLE_EQ(choice.gcv, problem.gcv(choice.lambda));
  // Neighbours on a fine log grid around the choice, and a coarse grid over 20 decades, are not
  // lower.
  for (double f : {0.5, 0.8, 0.9, 0.99, 1.01, 1.1, 1.25, 2.0}) {
    EXPECT_GE(problem.gcv(choice.lambda * f), choice.gcv * (1 - 1e-12)) << "factor " << f;
  }
  for (int e = -10; e <= 10; ++e) {
    EXPECT_GE(problem.gcv(choice.lambda * std::pow(10.0, e)), choice.gcv * (1 - 1e-12)) << "1e" << e;
  }
}

TEST(RbfGcv, ChoosesMoreSmoothingAsNoiseGrows) {
  const std::uint64_t seed = test::test_seed(test::kTalkingMarkerSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  const Problem p = make_problem(seed);
  const Eigen::MatrixXd e = noise(p.targets.rows(), p.targets.cols(), seed + 4);
  double previous = 0;
  for (double sigma : {3e-4, 3e-3, 3e-2}) {
    const RbfRidgeProblem problem(p.centres, p.targets + sigma * e, p.r_squared);
    const LambdaChoice choice = problem.choose_lambda();
    EXPECT_GT(choice.lambda, previous) << "noise " << sigma;
    previous = choice.lambda;
  }
}

// A known smooth deformation of the source markers: the RBF map learned from 21 prototypes
// predicts held-out frames better (mean squared error below half) than leaving the markers where they are (identity) or
// using the mean prototype (constant).
TEST(RbfRetarget, LearnsASmoothMapBetterThanTheBaselines) {
  const std::uint64_t seed = test::test_seed(test::kTalkingMarkerSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  const Eigen::MatrixXd a = test::articulation(6000, seed);
  const Eigen::MatrixXd source = test::smooth_shape_map(a, 60, seed + 1);
  Eigen::MatrixXd deformation = 0.5 * test::smooth_shape_map(a, 60, seed + 5);
  deformation.colwise() -= deformation.rowwise().mean();
  const Eigen::MatrixXd target = source + deformation;

  const Eigen::MatrixXd train = source.leftCols(3000);
  const auto picked = test::spread_frames(a.leftCols(3000), kPrototypes);
  RunningSpread spread(60);
  for (Eigen::Index t = 0; t < train.cols(); ++t) spread.add(train.col(t));
  LambdaChoice choice;
  const RbfMap map = fit_rbf_by_gcv(test::as_rows(train, picked), test::as_rows(target, picked),
                                    spread.mean_squared_distance(), &choice);
  const Eigen::VectorXd mean_prototype = test::as_rows(target, picked).colwise().mean().transpose();
  double rbf = 0, identity = 0, constant = 0;
  for (Eigen::Index t = 3000; t < 6000; ++t) {  // held out: never seen by the fit
    rbf += (map(source.col(t)) - target.col(t)).squaredNorm();
    identity += (source.col(t) - target.col(t)).squaredNorm();
    constant += (mean_prototype - target.col(t)).squaredNorm();
  }
  EXPECT_LT(rbf, 0.5 * identity) << "rbf " << std::sqrt(rbf / 3000) << " identity "
                                 << std::sqrt(identity / 3000) << " lambda " << choice.lambda;
  EXPECT_LT(rbf, 0.5 * constant) << "constant " << std::sqrt(constant / 3000);
}

TEST(RbfRetarget, OneBasisServesEveryOutputAndFarPointsFallBackToTheIntercept) {
  const std::uint64_t seed = test::test_seed(test::kTalkingMarkerSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  const Problem p = make_problem(seed);
  const double lambda = 1e-3;
  const RbfMap all = RbfRidgeProblem(p.centres, p.targets, p.r_squared).solve(lambda);
  const RbfMap left = RbfRidgeProblem(p.centres, p.targets.leftCols(40), p.r_squared).solve(lambda);
  const RbfMap right = RbfRidgeProblem(p.centres, p.targets.rightCols(50), p.r_squared).solve(lambda);
  EXPECT_LT((all.weights().leftCols(40) - left.weights()).norm(), 1e-9 * all.weights().norm());
  EXPECT_LT((all.weights().rightCols(50) - right.weights()).norm(), 1e-9 * all.weights().norm());

  const Eigen::VectorXd far = Eigen::VectorXd::Constant(60, 1e3);
  EXPECT_LT((all(far) - all.offset()).norm(), 1e-12);
  // map_columns (the streaming float path) agrees with the one-frame path.
  Eigen::MatrixXf out(90, 5);
  all.map_columns(p.corpus.leftCols(5), out);
  for (Eigen::Index t = 0; t < 5; ++t) {
    EXPECT_LT((out.col(t).cast<double>() - all(p.corpus.col(t))).norm(), 1e-5 * all(p.corpus.col(t)).norm());
  }
}

TEST(RbfRetarget, RefusesBadShapes) {
  const Eigen::MatrixXd c = Eigen::MatrixXd::Random(3, 4);
  EXPECT_THROW(RbfRidgeProblem(c, Eigen::MatrixXd::Zero(2, 5), 1.0), std::invalid_argument);
  EXPECT_THROW(RbfRidgeProblem(c.topRows(1), Eigen::MatrixXd::Zero(1, 5), 1.0), std::invalid_argument);
  EXPECT_THROW(RbfRidgeProblem(c, Eigen::MatrixXd::Zero(3, 5), 0.0), std::invalid_argument);
  const RbfRidgeProblem ok(c, Eigen::MatrixXd::Zero(3, 5), 1.0);
  EXPECT_THROW(ok.solve(-1.0), std::invalid_argument);
  EXPECT_THROW(ok.solve(0.0).responses(Eigen::VectorXd::Zero(3)), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
