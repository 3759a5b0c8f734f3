#include "fapcast/capture/head_pose.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fapcast {

Eigen::Matrix3Xd rigid_reference(const MarkerFrames<Centimetres>& frames, std::span<const std::size_t> rigid_rows,
                                 Eigen::Index frame) {
  Eigen::Matrix3Xd ref(3, static_cast<Eigen::Index>(rigid_rows.size()));
  for (std::size_t r = 0; r < rigid_rows.size(); ++r) {
    const auto m = static_cast<Eigen::Index>(rigid_rows[r]);
    if (m >= frames.marker_count() || !frames.present(m, frame))
      throw std::invalid_argument("rigid_reference: rigid marker row " + std::to_string(m) +
                                  " missing at frame " + std::to_string(frame));
    ref.col(static_cast<Eigen::Index>(r)) = frames.at(m, frame);
  }
  return ref;
}

PoseRemovalResult remove_head_pose(const MarkerFrames<Centimetres>& captured,
                                   std::span<const std::size_t> rigid_rows,
                                   const Eigen::Matrix3Xd& reference_cm) {
  if (reference_cm.cols() != static_cast<Eigen::Index>(rigid_rows.size()))
    throw std::invalid_argument("remove_head_pose: " + std::to_string(rigid_rows.size()) +
                                " rigid markers, reference has " +
                                std::to_string(reference_cm.cols()));
  for (const auto row : rigid_rows)
    if (static_cast<Eigen::Index>(row) >= captured.marker_count())
      throw std::invalid_argument("remove_head_pose: rigid marker row " + std::to_string(row) +
                                  " outside a take of " + std::to_string(captured.marker_count()) +
                                  " markers");
  PoseRemovalResult result;
  result.frames = captured;
  result.head_pose.resize(static_cast<std::size_t>(captured.frame_count()));
  double squared = 0;
  std::size_t samples = 0;
  Eigen::Matrix3Xd from(3, reference_cm.cols());
  Eigen::Matrix3Xd to(3, reference_cm.cols());
  for (Eigen::Index k = 0; k < captured.frame_count(); ++k) {
    Eigen::Index n = 0;
    for (std::size_t r = 0; r < rigid_rows.size(); ++r) {
      const auto m = static_cast<Eigen::Index>(rigid_rows[r]);
      if (!captured.present(m, k)) continue;
      from.col(n) = reference_cm.col(static_cast<Eigen::Index>(r));
      to.col(n) = captured.at(m, k);
      ++n;
    }
    RigidTransform pose;
    bool fitted = n >= 3;
    if (fitted) {
      try {
        pose = fit_rigid_transform(from.leftCols(n), to.leftCols(n));
      } catch (const std::invalid_argument&) {
        fitted = false;  // collinear survivors: pose undetermined
      }
    }
    if (!fitted) {
      result.frames_without_pose.push_back(k);
      result.frames.positions.col(k).setConstant(std::nan(""));
      continue;
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      squared += (pose.apply(from.col(i)) - to.col(i)).squaredNorm();
      ++samples;
    }
    result.head_pose[static_cast<std::size_t>(k)] = pose;
    const RigidTransform undo = pose.inverse();
    for (Eigen::Index m = 0; m < captured.marker_count(); ++m)
      if (captured.present(m, k))
        result.frames.positions.block<3, 1>(3 * m, k) = undo.apply(captured.at(m, k));
  }
  result.rms_rigid_residual_cm = samples > 0 ? std::sqrt(squared / static_cast<double>(samples)) : 0;
  return result;
}

}  // namespace fapcast
