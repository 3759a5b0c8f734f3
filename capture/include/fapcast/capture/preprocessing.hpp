#pragma once
// Capture preprocessing (paper section 3.3) in one call: short gaps filled, head-pose removal, then
// the long gaps of the face markers pattern-filled.
#include <Eigen/Core>

#include <cstddef>
#include <span>

#include "fapcast/capture/gap_fill.hpp"
#include "fapcast/capture/head_pose.hpp"
#include "fapcast/capture/pattern_fill.hpp"
#include "fapcast/corpus/marker_frames.hpp"

namespace fapcast {

struct PreprocessedTake {
  MarkerFrames<Centimetres> frames;  // head-stabilised, short gaps filled, long ones pattern-filled
  std::vector<MarkerGap> gaps;                    // every gap, spline-filled or reported
  std::vector<PatternFilledGap> pattern_filled;   // the reported gaps a donor filled
  std::vector<Eigen::Index> frames_without_pose;  // fewer than 3 rigid markers
  double rms_rigid_residual_cm = 0;
};

// Fills short gaps (in the capture frame, where trajectories are smooth), then removes the head
// pose using the rigid markers at `rigid_rows` (marker indices of `captured`, e.g.
// rigid_marker_rows() of the marker table) against `rigid_reference_cm` (3 x rigid_rows.size(),
// in the same order: the actor's neutral rigid markers or rigid_reference() of a chosen frame),
// then pattern-fills what is still missing of the other markers from each other (pattern_fill.hpp).
PreprocessedTake preprocess_take(const MarkerFrames<Centimetres>& captured, std::span<const std::size_t> rigid_rows,
                                 const Eigen::Matrix3Xd& rigid_reference_cm, const GapFillOptions& gap_options = {});

}  // namespace fapcast
