// The reference talker's takes through capture clean-up: pose removal recovers the face motion
// to within the capture noise, and gap filling restores the dropped samples close to the truth.
#include "fapcast/talker/reference_talker.hpp"

#include "fapcast/capture/gap_fill.hpp"
#include "fapcast/capture/head_pose.hpp"
#include "fapcast/face/marker_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace fapcast {
namespace {

ScriptItem word(const std::string& text) { return {ScriptSection::kCommonWord, text, {}, "", 0.0}; }

const FaceModel& actor() {
  static const FaceModel a = reference_actor(ict_face_model(), 7);
  return a;
}

// RMS (cm) of the difference between two takes over the frames both have and the samples
// present in both.
double rms_difference(const MarkerFrames<Centimetres>& a, const MarkerFrames<Centimetres>& b) {
  double sum = 0;
  std::size_t n = 0;
  for (Eigen::Index k = 0; k < std::min(a.frame_count(), b.frame_count()); ++k)
    for (Eigen::Index m = 0; m < a.marker_count(); ++m)
      if (a.present(m, k) && b.present(m, k)) {
        sum += (a.at(m, k) - b.at(m, k)).squaredNorm();
        ++n;
      }
  return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

TEST(ReferenceTalker, PoseRemovalRecoversTheFaceToWithinTheNoise) {
  PortableRandom random(12);
  const ReferenceTake take = record_take(word("mushrooms"), "utt0002", actor(), random);
  const auto rigid = rigid_marker_rows();
  ASSERT_GE(rigid.size(), 4u);
  const PoseRemovalResult pose = remove_head_pose(take.captured, rigid, rigid_reference(take.clean, rigid, 0));
  // The head moved by up to 3 degrees and 3 mm: without pose removal the markers are far off.
  EXPECT_GT(rms_difference(take.captured, take.clean), 0.05);
  // Noise is 0.2 mm per coordinate (0.35 mm in 3-D). The rigid fit adds its own error, which
  // the lever arm from the head markers to the mouth enlarges: within twice the noise.
  EXPECT_LT(rms_difference(pose.frames, take.clean), 0.07) << "cm";
  EXPECT_LT(pose.rms_rigid_residual_cm, 0.05);
  // Gap filling then restores the dropped samples it may fill, close to the truth.
  const GapFillResult filled = fill_gaps(pose.frames);
  EXPECT_LT(rms_difference(filled.frames, take.clean), 0.08);
}

}  // namespace
}  // namespace fapcast
