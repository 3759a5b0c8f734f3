#include "fapcast/math/pca_basis.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fapcast {

double PcaBasis::explained_fraction() const {
  return total_variance > 0.0 ? std::min(1.0, variances.sum() / total_variance) : 1.0;
}

Eigen::VectorXd PcaBasis::project(const Eigen::Ref<const Eigen::VectorXd>& frame) const {
  if (frame.size() != dimension()) throw std::invalid_argument("PcaBasis::project: wrong length");
  return components.transpose() * (frame - mean);
}

Eigen::VectorXd PcaBasis::reconstruct(const Eigen::Ref<const Eigen::VectorXd>& coefficients) const {
  if (coefficients.size() != size()) {
    throw std::invalid_argument("PcaBasis::reconstruct: wrong number of coefficients");
  }
  return mean + components * coefficients;
}

Eigen::MatrixXd orthonormal_basis(const Eigen::MatrixXd& a) {
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
  return qr.householderQ() * Eigen::MatrixXd::Identity(a.rows(), a.cols());
}

Eigen::VectorXd principal_angles(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.cols() < 1 || a.rows() < a.cols()) {
    throw std::invalid_argument("principal_angles: need two D x k matrices with D >= k >= 1");
  }
  const Eigen::MatrixXd qa = orthonormal_basis(a);
  const Eigen::MatrixXd qb = orthonormal_basis(b);
  const Eigen::MatrixXd overlap = qa.transpose() * qb;
  // Cosines come from the overlap, sines from what of b lies outside a; pairing them with atan2
  // keeps small angles accurate (acos of a cosine near 1 would not).
  const Eigen::VectorXd cosines = Eigen::JacobiSVD<Eigen::MatrixXd>(overlap).singularValues();
  const Eigen::VectorXd sines =
      Eigen::JacobiSVD<Eigen::MatrixXd>(qb - qa * overlap).singularValues();
  const Eigen::Index k = a.cols();
  Eigen::VectorXd angles(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    // cosines descend, sines descend: angle i pairs the i-th largest cosine with the i-th
    // smallest sine.
    angles[i] = std::atan2(std::clamp(sines[k - 1 - i], 0.0, 1.0), std::clamp(cosines[i], 0.0, 1.0));
  }
  return angles;
}

}  // namespace fapcast
