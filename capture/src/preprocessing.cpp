#include "fapcast/capture/preprocessing.hpp"

namespace fapcast {

PreprocessedTake preprocess_take(const MarkerFrames<Centimetres>& captured, std::span<const std::size_t> rigid_rows,
                                 const Eigen::Matrix3Xd& rigid_reference_cm, const GapFillOptions& gap_options) {
  GapFillResult filled = fill_gaps(captured, gap_options);
  PoseRemovalResult pose = remove_head_pose(filled.frames, rigid_rows, rigid_reference_cm);
  return {std::move(pose.frames), std::move(filled.gaps), std::move(pose.frames_without_pose),
          pose.rms_rigid_residual_cm};
}

}  // namespace fapcast
