#pragma once
// Bounded least squares in its normal-equation form, pre-factored once: the box-constrained convex
// quadratic  min 1/2 x'Hx - q'x  subject to lo <= x <= hi  for many right-hand sides q with the same
// H (spec/rigs.md, "The fit"). H (n x n, symmetric positive definite, 1 <= n <= kMaxBoxQpSize) is
// inverted once; a solve then starts from the unconstrained optimum u = H^-1 q and works in range
// space: for a set Z of variables held at a bound it factors only the |Z| x |Z| block (H^-1)_ZZ,
//   lambda = ((H^-1)_ZZ)^-1 (u_Z - x_Z),   x = u - (H^-1)_:Z lambda,
// where lambda are the bound constraints' multipliers (the gradient Hx - q at Z is -lambda). A primal
// active-set loop (add the first bound a step crosses, release the bound whose multiplier has the
// wrong sign most) ends when x is feasible and every multiplier has the right sign: the KKT
// conditions hold, so x is the exact minimiser (unique: H is positive definite).
#include <Eigen/Core>
#include <cstdint>
#include <span>

namespace fapcast {

inline constexpr int kMaxBoxQpSize = 64;

// What a solve did; `iterations` counts subproblems solved.
struct BoxQpStats {
  std::int64_t solves = 0;
  std::int64_t iterations = 0;
};

class BoxQp {
 public:
  // Throws std::invalid_argument unless H is square, 1..kMaxBoxQpSize, finite and positive
  // definite (its Cholesky factorisation succeeds), and lo <= hi element-wise (sizes n).
  BoxQp(const Eigen::MatrixXd& H, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi);

  int size() const { return static_cast<int>(h_inverse_.rows()); }
  const Eigen::MatrixXd& inverse() const { return h_inverse_; }

  // Warm state carried from one solve to the next (e.g. frame to frame): the last solution and
  // which variables were held at a bound. A default WarmStart starts from lo, all bound.
  struct WarmStart {
    Eigen::VectorXd x;
    std::uint64_t bound = 0;  // bit i: variable i held at lo[i] or hi[i] (whichever x[i] equals)
  };

  // Minimises for the unconstrained optimum u = H^-1 q (callers that solve many q of the form
  // a + G c keep H^-1 a and H^-1 G and pass u directly). `warm` is updated to the solution.
  // Returns the solution; throws std::logic_error if the active-set loop does not converge in
  // 4n + 8 subproblems (cannot happen for a positive definite H barring NaN input).
  const Eigen::VectorXd& solve_from_unconstrained(const Eigen::VectorXd& u, WarmStart& warm,
                                                  BoxQpStats* stats = nullptr) const;

 private:
  Eigen::MatrixXd h_inverse_;
  Eigen::VectorXd lo_, hi_;
};

}  // namespace fapcast
