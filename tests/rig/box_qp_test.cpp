// BoxQp against a brute-force enumeration of every active set (small n) and a projected-gradient
// reference (n = 32): the range-space active-set method must give the exact minimiser.
#include "fapcast/rig/box_qp.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

namespace fapcast {
namespace {

unsigned seed() { const char* s = std::getenv("FAPCAST_TEST_SEED"); return s ? static_cast<unsigned>(std::atoi(s)) : 20u; }

Eigen::MatrixXd random_spd(int n, std::mt19937& rng, double condition) {
  std::normal_distribution<double> g;
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a(i, j) = g(rng);
  Eigen::MatrixXd h = a * a.transpose() / n + Eigen::MatrixXd::Identity(n, n) / condition;
  return 0.5 * (h + h.transpose());
}

double objective(const Eigen::MatrixXd& h, const Eigen::VectorXd& q, const Eigen::VectorXd& x) {
  return 0.5 * x.dot(h * x) - q.dot(x);
}

// Every assignment of each variable to lo, hi or free: the one whose free subsystem's solution is
// feasible and whose bound gradients have the right signs is the minimiser.
Eigen::VectorXd brute_force(const Eigen::MatrixXd& h, const Eigen::VectorXd& q, const Eigen::VectorXd& lo,
                            const Eigen::VectorXd& hi) {
  const int n = static_cast<int>(q.size());
  int total = 1;
  for (int i = 0; i < n; ++i) total *= 3;
  Eigen::VectorXd best;
  double best_value = INFINITY;
  for (int code = 0; code < total; ++code) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    std::vector<int> state(static_cast<std::size_t>(n)), free_;
    for (int i = 0, c = code; i < n; ++i, c /= 3) state[static_cast<std::size_t>(i)] = c % 3;
    for (int i = 0; i < n; ++i) {
      if (state[static_cast<std::size_t>(i)] == 0) x[i] = lo[i];
      else if (state[static_cast<std::size_t>(i)] == 1) x[i] = hi[i];
      else free_.push_back(i);
    }
    if (!free_.empty()) {
      const int m = static_cast<int>(free_.size());
      Eigen::MatrixXd hf(m, m);
      Eigen::VectorXd r(m);
      for (int a = 0; a < m; ++a) {
        r[a] = q[free_[static_cast<std::size_t>(a)]];
        for (int j = 0; j < n; ++j)
          if (state[static_cast<std::size_t>(j)] != 2) r[a] -= h(free_[static_cast<std::size_t>(a)], j) * x[j];
        for (int b = 0; b < m; ++b) hf(a, b) = h(free_[static_cast<std::size_t>(a)], free_[static_cast<std::size_t>(b)]);
      }
      const Eigen::VectorXd xf = hf.llt().solve(r);
      bool inside = true;
      for (int a = 0; a < m; ++a) {
        const int i = free_[static_cast<std::size_t>(a)];
        x[i] = xf[a];
        inside = inside && xf[a] >= lo[i] - 1e-12 && xf[a] <= hi[i] + 1e-12;
      }
      if (!inside) continue;
    }
    const double v = objective(h, q, x);
    if (v < best_value) { best_value = v; best = x; }
  }
  return best;
}

TEST(BoxQp, MatchesEveryActiveSetEnumerated) {
  std::mt19937 rng(seed());
  std::uniform_real_distribution<double> u(-2, 2);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 1 + trial % 7;
    const Eigen::MatrixXd h = random_spd(n, rng, trial % 2 ? 1e3 : 10.0);
    Eigen::VectorXd lo(n), hi(n), q(n);
    for (int i = 0; i < n; ++i) {
      lo[i] = trial % 3 ? 0.0 : u(rng) - 1;
      hi[i] = trial % 3 ? 1.0 : lo[i] + 0.1 + std::abs(u(rng));
      q[i] = 2 * u(rng);
    }
    const BoxQp qp(h, lo, hi);
    BoxQp::WarmStart warm;
    BoxQpStats stats;
    const Eigen::VectorXd x = qp.solve_from_unconstrained(qp.inverse() * q, warm, &stats);
    const Eigen::VectorXd want = brute_force(h, q, lo, hi);
    ASSERT_LE((x - want).cwiseAbs().maxCoeff(), 1e-9) << "trial " << trial << " n " << n << " (FAPCAST_TEST_SEED=" << seed() << ")";
    // a warm start from another problem's state reaches the same point
    BoxQp::WarmStart other;
    other.x = Eigen::VectorXd::Constant(n, 0.5).cwiseMax(lo).cwiseMin(hi);
    other.bound = 0b1010101 & ((1u << n) - 1);
    EXPECT_LE((qp.solve_from_unconstrained(qp.inverse() * q, other) - want).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(BoxQp, BeatsProjectedGradientAtThirtyTwo) {
  std::mt19937 rng(seed() + 1);
  std::uniform_real_distribution<double> u(-1, 1);
  const int n = 32;
  const Eigen::MatrixXd h = random_spd(n, rng, 1e4);
  const BoxQp qp(h, Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n));
  const double step = 1.0 / Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(h).eigenvalues().maxCoeff();
  BoxQp::WarmStart warm;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd q(n);
    for (int i = 0; i < n; ++i) q[i] = u(rng);
    const Eigen::VectorXd x = qp.solve_from_unconstrained(qp.inverse() * q, warm);
    ASSERT_TRUE((x.array() >= 0).all() && (x.array() <= 1).all());
    Eigen::VectorXd p = Eigen::VectorXd::Constant(n, 0.5);
    for (int it = 0; it < 20000; ++it) p = (p - step * (h * p - q)).cwiseMax(0.0).cwiseMin(1.0);
    EXPECT_LE(objective(h, q, x), objective(h, q, p) + 1e-12) << "trial " << trial;
    // KKT: free variables have zero gradient, bound ones the right sign
    const Eigen::VectorXd g = h * x - q;
    for (int i = 0; i < n; ++i) {
      if (x[i] > 0 && x[i] < 1) {
        EXPECT_NEAR(g[i], 0.0, 1e-9);
      } else if (x[i] == 0) {
        EXPECT_GE(g[i], -1e-9);
      } else {
        EXPECT_LE(g[i], 1e-9);
      }
    }
  }
}

TEST(BoxQp, RefusesWhatIsNotAStrictlyConvexBox) {
  const Eigen::VectorXd lo = Eigen::VectorXd::Zero(2), hi = Eigen::VectorXd::Ones(2);
  EXPECT_THROW(BoxQp(Eigen::MatrixXd::Zero(2, 2), lo, hi), std::invalid_argument);
  EXPECT_THROW(BoxQp(Eigen::MatrixXd::Identity(2, 3), lo, hi), std::invalid_argument);
  EXPECT_THROW(BoxQp(Eigen::MatrixXd::Identity(2, 2), hi, lo), std::invalid_argument);
  EXPECT_THROW(BoxQp(Eigen::MatrixXd::Identity(65, 65), Eigen::VectorXd::Zero(65), Eigen::VectorXd::Ones(65)),
               std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
