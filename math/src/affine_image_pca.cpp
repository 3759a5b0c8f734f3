#include "fapcast/math/affine_image_pca.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <stdexcept>
#include <string>

namespace fapcast {

PcaBasis pca_of_affine_image(const Eigen::MatrixXd& weights, const Eigen::VectorXd& offset,
                             const Eigen::VectorXd& response_mean,
                             const Eigen::MatrixXd& response_covariance, int k) {
  const Eigen::Index m = weights.rows();
  const Eigen::Index d = weights.cols();
  if (m < 1 || offset.size() != d || response_mean.size() != m ||
      response_covariance.rows() != m || response_covariance.cols() != m) {
    throw std::invalid_argument("pca_of_affine_image: weights m x D, offset D, mean m, cov m x m");
  }
  if (k < 1 || k > m || k > d) {
    throw std::invalid_argument("pca_of_affine_image: k = " + std::to_string(k) +
                                " outside [1, min(m, D)] = [1, " + std::to_string(std::min(m, d)) + "]");
  }
  // Cov(phi) = V diag(e) V^T = L L^T with L = V diag(sqrt(e)); tiny negative eigenvalues from
  // rounding are clamped (the covariance is positive semi-definite in exact arithmetic).
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(response_covariance);
  const Eigen::MatrixXd l =
      eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();

  // Thin QR of W^T (D x m): W^T = Q R, so Cov(y) = Q (R L)(R L)^T Q^T.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(weights.transpose());
  const Eigen::MatrixXd r =
      qr.matrixQR().topRows(std::min(m, d)).triangularView<Eigen::Upper>();  // min(m,D) x m
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(r * l, Eigen::ComputeThinU);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(d, std::min(m, d));

  PcaBasis basis;
  basis.mean = offset + weights.transpose() * response_mean;
  basis.components = q * svd.matrixU().leftCols(k);
  basis.variances = svd.singularValues().head(k).array().square().matrix();
  basis.total_variance = svd.singularValues().squaredNorm();
  basis.iterations = 0;
  basis.converged = true;
  return basis;
}

}  // namespace fapcast
