// The reference talker's takes through capture clean-up: pose removal recovers the face motion
// to within the capture noise, and gap filling restores the dropped samples close to the truth.
#include "fapcast/talker/reference_talker.hpp"

#include "fapcast/capture/gap_fill.hpp"
#include "fapcast/capture/head_pose.hpp"
#include "fapcast/face/marker_map.hpp"

#include "support/reference_takes.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

using test::rms_difference;
using test::script_word;
using test::test_actor;

TEST(ReferenceTalker, PoseRemovalRecoversTheFaceToWithinTheNoise) {
  PortableRandom random(12);
  const ReferenceTake take = record_take(script_word("mushrooms"), "utt0002", test_actor(), random);
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
