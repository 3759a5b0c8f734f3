#pragma once
// A PCA basis of D-dimensional frames (D = 3N mesh coordinates): the mean frame, k orthonormal
// components and the variance each explains - what the voice stores (paper section 3.6) and the
// search emits coefficients against.
#include <Eigen/Core>

namespace fapcast {

struct PcaBasis {
  Eigen::VectorXd mean;        // D
  Eigen::MatrixXd components;  // D x k, orthonormal columns, by decreasing variance
  Eigen::VectorXd variances;   // k, population variance (divided by the frame count) along each
  double total_variance = 0;   // trace of the frame covariance (all directions, not only k)
  int iterations = 0;          // passes of the iterative method (0 for the exact route)
  bool converged = true;

  Eigen::Index dimension() const { return components.rows(); }
  Eigen::Index size() const { return components.cols(); }
  // Share of the total variance the k components explain, in [0, 1].
  double explained_fraction() const;
  // Coefficients of one frame (length D): components^T (y - mean).
  Eigen::VectorXd project(const Eigen::Ref<const Eigen::VectorXd>& frame) const;
  // The frame rebuilt from k coefficients: mean + components * coefficients.
  Eigen::VectorXd reconstruct(const Eigen::Ref<const Eigen::VectorXd>& coefficients) const;
};

// Principal angles (radians, ascending) between the column spaces of a and b (both D x k with
// full column rank, the same k). Computed from sines, so angles near 0 keep their accuracy.
Eigen::VectorXd principal_angles(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

// An orthonormal basis (D x k) of the column space of a (D x k, full column rank): thin QR.
Eigen::MatrixXd orthonormal_basis(const Eigen::MatrixXd& a);

}  // namespace fapcast
