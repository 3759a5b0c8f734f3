#include "fapcast/synth/preprocessing.hpp"

#include "fapcast/synth/marker_map.hpp"

namespace fapcast::synth {

PreprocessedTake preprocess_take(const MarkerFrames& captured, const Eigen::Matrix3Xd& rigid_reference_cm,
                                 const GapFillOptions& gap_options) {
  GapFillResult filled = fill_gaps(captured, gap_options);
  const auto rigid = rigid_marker_rows();
  PoseRemovalResult pose = remove_head_pose(filled.frames, rigid, rigid_reference_cm);
  return {std::move(pose.frames), std::move(filled.gaps), std::move(pose.frames_without_pose),
          pose.rms_rigid_residual_cm};
}

}  // namespace fapcast::synth
