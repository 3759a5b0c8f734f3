#pragma once
// Capture preprocessing (paper section 3.3) in one call: gap filling, then head-pose removal.
#include <Eigen/Core>

#include <cstddef>
#include <span>

#include "fapcast/capture/gap_fill.hpp"
#include "fapcast/capture/head_pose.hpp"
#include "fapcast/corpus/marker_frames.hpp"

namespace fapcast {

struct PreprocessedTake {
  MarkerFrames<Centimetres> frames;                            // head-stabilised, short gaps filled
  std::vector<MarkerGap> gaps;                    // every gap, filled or reported
  std::vector<Eigen::Index> frames_without_pose;  // fewer than 3 rigid markers
  double rms_rigid_residual_cm = 0;
};

// Fills short gaps (in the capture frame, where trajectories are smooth), then removes the head
// pose using the rigid markers at `rigid_rows` (marker indices of `captured`, e.g.
// rigid_marker_rows() of the marker table) against `rigid_reference_cm` (3 x rigid_rows.size(),
// in the same order: the actor's neutral rigid markers or rigid_reference() of a chosen frame).
PreprocessedTake preprocess_take(const MarkerFrames<Centimetres>& captured, std::span<const std::size_t> rigid_rows,
                                 const Eigen::Matrix3Xd& rigid_reference_cm, const GapFillOptions& gap_options = {});

}  // namespace fapcast
