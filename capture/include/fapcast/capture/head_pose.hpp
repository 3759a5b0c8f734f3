#pragma once
// Head-pose removal (paper section 3.3): per frame, a least-squares rigid fit of the rigid head
// markers to their reference positions; every marker is then mapped into the head's frame.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "fapcast/corpus/marker_frames.hpp"
#include "fapcast/math/rigid_transform.hpp"

namespace fapcast {

struct PoseRemovalResult {
  MarkerFrames<Centimetres> frames;                    // markers in the head frame (the reference's frame)
  std::vector<RigidTransform> head_pose;  // per frame: captured = pose.apply(head frame)
  std::vector<Eigen::Index> frames_without_pose;  // fewer than 3 rigid markers: all set missing
  double rms_rigid_residual_cm = 0;       // fit residual over every rigid marker sample used
};

// Reference positions (3 x R) of the rigid markers at one frame; throws if any is missing.
Eigen::Matrix3Xd rigid_reference(const MarkerFrames<Centimetres>& frames, std::span<const std::size_t> rigid_rows,
                                 Eigen::Index frame);

// Removes head motion: fits each frame's present rigid markers (>= 3) to `reference_cm`
// (3 x rigid_rows.size(), same order) and applies the inverse motion to all markers.
PoseRemovalResult remove_head_pose(const MarkerFrames<Centimetres>& captured,
                                   std::span<const std::size_t> rigid_rows,
                                   const Eigen::Matrix3Xd& reference_cm);

}  // namespace fapcast
