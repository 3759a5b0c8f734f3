#include "fapcast/rig/box_qp.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>

namespace fapcast {

BoxQp::BoxQp(const Eigen::MatrixXd& H, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  const Eigen::Index n = H.rows();
  if (n < 1 || n > kMaxBoxQpSize || H.cols() != n || lo.size() != n || hi.size() != n)
    throw std::invalid_argument("BoxQp: H must be square, 1.." + std::to_string(kMaxBoxQpSize) +
                                ", with bounds of its size");
  if (!H.allFinite() || !lo.allFinite() || !hi.allFinite())
    throw std::invalid_argument("BoxQp: non-finite H or bounds");
  if ((lo.array() > hi.array()).any()) throw std::invalid_argument("BoxQp: lo > hi");
  Eigen::LLT<Eigen::MatrixXd> llt(0.5 * (H + H.transpose()));
  if (llt.info() != Eigen::Success) throw std::invalid_argument("BoxQp: H is not positive definite");
  h_inverse_ = llt.solve(Eigen::MatrixXd::Identity(n, n));
  h_inverse_ = 0.5 * (h_inverse_ + h_inverse_.transpose());
  lo_ = lo;
  hi_ = hi;
}

const Eigen::VectorXd& BoxQp::solve_from_unconstrained(const Eigen::VectorXd& u, WarmStart& warm,
                                                       BoxQpStats* stats) const {
  const int n = size();
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxBoxQpSize, kMaxBoxQpSize>;
  using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxBoxQpSize, 1>;
  Eigen::VectorXd& x = warm.x;
  if (x.size() != n) {
    x = lo_;
    warm.bound = n == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
  }
  // A bound variable sits exactly on the bound it is nearer to; a free one inside the box.
  for (int i = 0; i < n; ++i) {
    if (warm.bound >> i & 1)
      x[i] = std::abs(x[i] - lo_[i]) <= std::abs(hi_[i] - x[i]) ? lo_[i] : hi_[i];
    else
      x[i] = std::min(std::max(x[i], lo_[i]), hi_[i]);
  }
  int held[kMaxBoxQpSize];
  Small block;
  SmallVector rhs, lambda;
  Eigen::LLT<Small> llt;
  Eigen::VectorXd target(n);
  const int limit = 4 * n + 8;
  if (stats) ++stats->solves;
  for (int iteration = 0; iteration < limit; ++iteration) {
    if (stats) ++stats->iterations;
    int z = 0;
    for (int i = 0; i < n; ++i)
      if (warm.bound >> i & 1) held[z++] = i;
    target = u;
    if (z > 0) {
      block.resize(z, z);
      rhs.resize(z);
      for (int r = 0; r < z; ++r) {
        rhs[r] = u[held[r]] - x[held[r]];
        for (int c = 0; c <= r; ++c) block(r, c) = h_inverse_(held[r], held[c]);
      }
      llt.compute(block);  // reads the lower triangle
      lambda = llt.solve(rhs);
      for (int r = 0; r < z; ++r) target.noalias() -= h_inverse_.col(held[r]) * lambda[r];
    }
    // Step from x towards the subproblem's optimum; stop at the first bound a free variable crosses.
    double step = 1.0;
    int blocking = -1;
    for (int i = 0; i < n; ++i) {
      if (warm.bound >> i & 1) continue;
      const double d = target[i] - x[i];
      if (target[i] < lo_[i] && d < 0) {
        const double s = (lo_[i] - x[i]) / d;
        if (s < step) { step = s; blocking = i; }
      } else if (target[i] > hi_[i] && d > 0) {
        const double s = (hi_[i] - x[i]) / d;
        if (s < step) { step = s; blocking = i; }
      }
    }
    for (int i = 0; i < n; ++i)
      if (!(warm.bound >> i & 1)) x[i] += step * (target[i] - x[i]);
    if (blocking >= 0) {
      x[blocking] = target[blocking] < lo_[blocking] ? lo_[blocking] : hi_[blocking];
      warm.bound |= std::uint64_t{1} << blocking;
      continue;
    }
    // x is the subproblem's optimum. At lo the gradient must be >= 0 (lambda <= 0), at hi <= 0.
    int worst = -1;
    double worst_violation = 1e-12 * (1.0 + u.cwiseAbs().maxCoeff());
    for (int r = 0; r < z; ++r) {
      const int i = held[r];
      const bool at_lo = x[i] == lo_[i] && lo_[i] != hi_[i];
      const bool at_hi = x[i] == hi_[i] && lo_[i] != hi_[i];
      const double violation = at_lo ? lambda[r] : at_hi ? -lambda[r] : 0.0;
      if (violation > worst_violation) { worst_violation = violation; worst = i; }
    }
    if (worst < 0) return x;
    warm.bound &= ~(std::uint64_t{1} << worst);
  }
  throw std::logic_error("BoxQp: the active-set loop did not converge (this is a bug, or NaN input)");
}

}  // namespace fapcast
