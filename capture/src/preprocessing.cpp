#include "fapcast/capture/preprocessing.hpp"

#include <algorithm>
#include <vector>

namespace fapcast {

PreprocessedTake preprocess_take(const MarkerFrames<Centimetres>& captured, std::span<const std::size_t> rigid_rows,
                                 const Eigen::Matrix3Xd& rigid_reference_cm, const GapFillOptions& gap_options) {
  GapFillResult filled = fill_gaps(captured, gap_options);
  PoseRemovalResult pose = remove_head_pose(filled.frames, rigid_rows, rigid_reference_cm);
  // Donors: every marker but the rigid ones, which do not move with the face.
  std::vector<std::size_t> donors;
  for (Eigen::Index m = 0; m < captured.marker_count(); ++m)
    if (std::find(rigid_rows.begin(), rigid_rows.end(), static_cast<std::size_t>(m)) == rigid_rows.end())
      donors.push_back(static_cast<std::size_t>(m));
  PatternFillResult patterned = pattern_fill(pose.frames, donors);
  return {std::move(patterned.frames), std::move(filled.gaps), std::move(patterned.filled),
          std::move(pose.frames_without_pose), pose.rms_rigid_residual_cm};
}

}  // namespace fapcast
