#pragma once
// The exact PCA of retargeted frames (paper section 3.6, made exact): every frame is
// y_t = b + W^T phi_t with phi_t the m basis responses of an RBF map (rbf_retarget.hpp), so
//   mean(y) = b + W^T mean(phi),   Cov(y) = W^T Cov(phi) W   (D x D, rank <= m).
// With Cov(phi) = L L^T and the thin QR W^T = Q R (D x m), Cov(y) = Q (R L)(R L)^T Q^T, so one
// SVD of the m x m matrix R L = U S V^T gives the components Q U and the variances S^2.
// Cost O(D m^2) after one O(frames m^2) pass over the responses - no D x D or frames x D matrix.
#include <Eigen/Core>

#include "fapcast/math/pca_basis.hpp"

namespace fapcast {

// PCA basis (k <= m components) of the affine image b + W^T phi of responses with the given mean
// (m) and covariance (m x m, symmetric positive semi-definite). `weights` is m x D, `offset` D.
// Throws std::invalid_argument on inconsistent shapes or k outside [1, m].
PcaBasis pca_of_affine_image(const Eigen::MatrixXd& weights, const Eigen::VectorXd& offset,
                             const Eigen::VectorXd& response_mean,
                             const Eigen::MatrixXd& response_covariance, int k);

}  // namespace fapcast
