#include "fapcast/math/rigid_transform.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <stdexcept>
#include <string>

namespace fapcast {

RigidTransform fit_rigid_transform(const Eigen::Matrix3Xd& from, const Eigen::Matrix3Xd& to) {
  if (from.cols() != to.cols())
    throw std::invalid_argument("fit_rigid_transform: " + std::to_string(from.cols()) +
                                " source points, " + std::to_string(to.cols()) + " target points");
  if (from.cols() < 3)
    throw std::invalid_argument("fit_rigid_transform: needs at least 3 points, got " +
                                std::to_string(from.cols()));
  const Eigen::Vector3d from_mean = from.rowwise().mean();
  const Eigen::Vector3d to_mean = to.rowwise().mean();
  const Eigen::Matrix3Xd a = from.colwise() - from_mean;
  const Eigen::Matrix3Xd b = to.colwise() - to_mean;
  const Eigen::Matrix3d h = a * b.transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto s = svd.singularValues();
  // Collinear or coincident points leave a rotation about their line undetermined.
  if (!(s(1) > 1e-9 * std::max(s(0), 1e-300)))
    throw std::invalid_argument("fit_rigid_transform: points are collinear or coincident");
  const Eigen::Matrix3d u = svd.matrixU();
  const Eigen::Matrix3d v = svd.matrixV();
  Eigen::Vector3d d(1.0, 1.0, (v * u.transpose()).determinant() < 0 ? -1.0 : 1.0);
  RigidTransform t;
  t.rotation = v * d.asDiagonal() * u.transpose();
  t.translation = to_mean - t.rotation * from_mean;
  return t;
}

}  // namespace fapcast
