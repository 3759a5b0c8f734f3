#pragma once
// Rigid motions and their least-squares fit to corresponding points (Kabsch / Horn).
#include <Eigen/Core>

namespace fapcast {

// y = rotation * x + translation; rotation is proper (det = +1).
struct RigidTransform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& x) const { return rotation * x + translation; }
  // The inverse motion: x = R^T (y - t).
  RigidTransform inverse() const {
    return {rotation.transpose(), -(rotation.transpose() * translation)};
  }
};

// The proper rotation and translation minimising sum_i |R from_i + t - to_i|^2 (Kabsch, with
// the reflection guard: when the best orthogonal map is a reflection the smallest singular
// direction is flipped). from and to are 3 x n with n >= 3 corresponding points; throws
// std::invalid_argument when n < 3, the sizes differ, or the points are (nearly) collinear.
RigidTransform fit_rigid_transform(const Eigen::Matrix3Xd& from, const Eigen::Matrix3Xd& to);

}  // namespace fapcast
