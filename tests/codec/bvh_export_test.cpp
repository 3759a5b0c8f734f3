#include "fapcast/codec/bvh_export.hpp"

#include "fapcast/codec/bvh_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace fapcast {
namespace {

const FaceGeometry kFace = generic_adult_face();
const FapuValues kFapu = measure_fapu(kFace.feature_points);

// Two frames: neutral, then `fap` = value. Exported, written, read back (so every check below
// also goes through the text format).
BvhDocument export_step(int fap, std::int32_t value, FrameRate rate = {25, 1}) {
  FapSequence seq{"step", rate, {FapFrame{}, FapFrame{}.set(fap, value)}};
  return read_bvh(write_bvh(fap_to_bvh(seq, kFace)), "step.bvh");
}

// World position of joint `name`'s origin at frame k.
Eigen::Vector3d world_position(const BvhDocument& doc, std::string_view name, std::uint64_t k) {
  const auto i = doc.find_joint(name);
  EXPECT_TRUE(i.has_value()) << "no joint " << name;
  return joint_world_transforms(doc, k).at(*i).translation();
}

TEST(BvhExport, GenericFaceHasTheDocumentedMeasures) {
  EXPECT_DOUBLE_EQ(kFapu.mns * 1024, 2.2);
  EXPECT_DOUBLE_EQ(kFapu.mw * 1024, 5.0);
  EXPECT_DOUBLE_EQ(kFapu.ens * 1024, 4.5);
  EXPECT_DOUBLE_EQ(kFapu.es * 1024, 6.4);
  EXPECT_NEAR(kFapu.irisd * 1024, 1.2, 1e-12);
  EXPECT_NEAR(kFace.jaw_length(), 11.856, 1e-3);
}

TEST(BvhExport, HierarchyIsWellFormedAndMatchesTheRig) {
  const BvhDocument doc = export_step(3, 100);
  ASSERT_EQ(doc.joints.size(), 2 + bvh_rig_points().size());
  EXPECT_EQ(doc.joints[0].name, kBvhHeadJoint);
  EXPECT_EQ(doc.joints[0].parent, -1);
  EXPECT_EQ(doc.joints[1].name, kBvhJawJoint);
  EXPECT_EQ(doc.joints[1].parent, 0);
  EXPECT_EQ(doc.channel_count(), 6 + 6 + 3 * bvh_rig_points().size());
  for (std::size_t i = 0; i < bvh_rig_points().size(); ++i) {
    const BvhRigPoint& p = bvh_rig_points()[i];
    const BvhJoint& j = doc.joints[i + 2];
    EXPECT_EQ(j.name, p.joint);
    EXPECT_EQ(j.parent, p.on_jaw ? 1 : 0) << j.name;
    EXPECT_EQ(j.channels.size(), 3u) << j.name;
    EXPECT_TRUE(j.end_site.has_value()) << j.name;
    // At rest every joint sits on its neutral feature point.
    EXPECT_TRUE(world_position(doc, j.name, 0).isApprox(kFace.at(p.fp), 1e-12)) << j.name;
  }
  EXPECT_EQ(doc.frame_count, 2u);
  EXPECT_DOUBLE_EQ(doc.frame_time_s, 0.04);
}

TEST(BvhExport, FrameTimeIsTheExactPeriodOfNtscRates) {
  const BvhDocument doc = export_step(3, 0, {30000, 1001});
  EXPECT_DOUBLE_EQ(doc.frame_time_s, 1001.0 / 30000.0);
}

TEST(BvhExport, WriteThenReadIsIdentity) {
  FapSequence seq{"mix", {25, 1}, {}};
  for (int k = 0; k < 30; ++k) {
    FapFrame f;
    for (int fap = 3; fap <= 68; ++fap) f.set(fap, (k * 37 + fap * 11) % 401 - 200);
    seq.frames.push_back(f);
  }
  const BvhDocument doc = fap_to_bvh(seq, kFace);
  EXPECT_EQ(read_bvh(write_bvh(doc), "mix.bvh"), doc);
}

// One lip or tongue FAP: the joint it must move, the face axis of its positive direction
// (x = face's left, y up, z forward) and its FAPU.
struct DirectionCase {
  int fap;
  std::string_view joint;
  Eigen::Vector3d axis;
  Fapu unit;
};
std::ostream& operator<<(std::ostream& out, const DirectionCase& c) {
  return out << "FAP " << c.fap << " " << fap_info(c.fap).name << " -> " << c.joint;
}

class BvhFapDirection : public testing::TestWithParam<DirectionCase> {};

TEST_P(BvhFapDirection, MovesItsJointAlongItsDocumentedDirection) {
  const DirectionCase& c = GetParam();
  constexpr std::int32_t kValue = 300;
  const BvhDocument doc = export_step(c.fap, kValue);
  const Eigen::Vector3d moved = world_position(doc, c.joint, 1) - world_position(doc, c.joint, 0);
  const Eigen::Vector3d expected = c.axis * kValue * kFapu.of(c.unit);
  EXPECT_TRUE(moved.isApprox(expected, 1e-9)) << "moved " << moved.transpose() << ", expected "
                                               << expected.transpose();
  // ... and nothing else in the rig moves.
  for (const BvhRigPoint& p : bvh_rig_points()) {
    if (p.joint == c.joint) continue;
    EXPECT_TRUE(world_position(doc, p.joint, 1).isApprox(world_position(doc, p.joint, 0), 1e-12))
        << p.joint << " moved too";
  }
}

const Eigen::Vector3d kUp = Eigen::Vector3d::UnitY(), kDown = -kUp;
const Eigen::Vector3d kLeft = Eigen::Vector3d::UnitX(), kRight = -kLeft;
const Eigen::Vector3d kForward = Eigen::Vector3d::UnitZ();

INSTANTIATE_TEST_SUITE_P(
    LipAndTongueFaps, BvhFapDirection,
    testing::Values(
        DirectionCase{4, "lip_2_2", kDown, Fapu::kMNS}, DirectionCase{5, "lip_2_3", kUp, Fapu::kMNS},
        DirectionCase{6, "lip_2_4", kLeft, Fapu::kMW}, DirectionCase{7, "lip_2_5", kRight, Fapu::kMW},
        DirectionCase{8, "lip_2_6", kDown, Fapu::kMNS}, DirectionCase{9, "lip_2_7", kDown, Fapu::kMNS},
        DirectionCase{10, "lip_2_8", kUp, Fapu::kMNS}, DirectionCase{11, "lip_2_9", kUp, Fapu::kMNS},
        DirectionCase{12, "lip_2_4", kUp, Fapu::kMNS}, DirectionCase{13, "lip_2_5", kUp, Fapu::kMNS},
        DirectionCase{16, "lip_2_3", kForward, Fapu::kMNS},
        DirectionCase{17, "lip_2_2", kForward, Fapu::kMNS},
        DirectionCase{51, "lip_8_1", kDown, Fapu::kMNS}, DirectionCase{52, "lip_8_2", kUp, Fapu::kMNS},
        DirectionCase{53, "lip_8_3", kLeft, Fapu::kMW}, DirectionCase{54, "lip_8_4", kRight, Fapu::kMW},
        DirectionCase{55, "lip_8_5", kDown, Fapu::kMNS}, DirectionCase{56, "lip_8_6", kDown, Fapu::kMNS},
        DirectionCase{57, "lip_8_7", kUp, Fapu::kMNS}, DirectionCase{58, "lip_8_8", kUp, Fapu::kMNS},
        DirectionCase{59, "lip_8_3", kUp, Fapu::kMNS}, DirectionCase{60, "lip_8_4", kUp, Fapu::kMNS},
        DirectionCase{43, "tongue_tip_6_1", kRight, Fapu::kMW},
        DirectionCase{44, "tongue_tip_6_1", kUp, Fapu::kMNS},
        DirectionCase{45, "tongue_tip_6_1", kForward, Fapu::kMW}));

// Head rotation FAPs: which face vector turns toward which, by value * 1e-5 rad.
struct HeadCase {
  int fap;
  Eigen::Vector3d turned;   // a unit vector fixed in the head ...
  Eigen::Vector3d towards;  // ... turns towards this one for positive values
};
class BvhHeadRotation : public testing::TestWithParam<HeadCase> {};

TEST_P(BvhHeadRotation, TurnsTheHeadTheDocumentedWayByTheAngleUnit) {
  const HeadCase& c = GetParam();
  constexpr std::int32_t kValue = 20000;  // 0.2 rad
  const BvhDocument doc = export_step(c.fap, kValue);
  const Eigen::Matrix3d r = joint_world_transforms(doc, 1)[0].linear();
  const Eigen::Vector3d v = r * c.turned;
  EXPECT_NEAR(std::acos(std::clamp(v.dot(c.turned), -1.0, 1.0)), kValue * 1e-5, 1e-12);
  EXPECT_NEAR(v.dot(c.towards), std::sin(kValue * 1e-5), 1e-12);
  EXPECT_TRUE(joint_world_transforms(doc, 1)[0].translation().isApprox(kFace.head_pivot));
}

INSTANTIATE_TEST_SUITE_P(HeadFaps, BvhHeadRotation,
                         testing::Values(HeadCase{48, kForward, kDown},   // head_pitch: down
                                         HeadCase{49, kForward, kLeft},   // head_yaw: left
                                         HeadCase{50, kUp, kRight}));     // head_roll: right

// The chin, FP 2.1, is not a joint: it rides on the jaw at (2.1 - jaw pivot).
Eigen::Vector3d chin(const BvhDocument& doc, std::uint64_t k) {
  return joint_world_transforms(doc, k)[1] * (kFace.at({2, 1}) - kFace.jaw_pivot);
}

TEST(BvhExport, OpenJawSwingsTheChinDownAlongAnArcOfOpenJawTimesMns) {
  for (std::int32_t value : {50, 400, 1080}) {
    const BvhDocument doc = export_step(3, value);
    const Eigen::Vector3d moved = chin(doc, 1) - chin(doc, 0);
    const double arc = value * kFapu.mns, L = kFace.jaw_length();
    EXPECT_NEAR(moved.norm(), 2 * L * std::sin(arc / L / 2), 1e-12) << value;  // chord of the arc
    EXPECT_LT(moved.y(), 0.0);
    EXPECT_NEAR(moved.x(), 0.0, 1e-12);
    // The lower lip goes with the jaw, the upper lip stays.
    EXPECT_LT(world_position(doc, "lip_2_3", 1).y(), world_position(doc, "lip_2_3", 0).y());
    EXPECT_TRUE(world_position(doc, "lip_2_2", 1).isApprox(world_position(doc, "lip_2_2", 0)));
  }
}

TEST(BvhExport, ShiftAndThrustJawTranslateTheChin) {
  const BvhDocument shift = export_step(15, 200);
  EXPECT_TRUE((chin(shift, 1) - chin(shift, 0)).isApprox(kRight * 200 * kFapu.mw, 1e-12));
  const BvhDocument thrust = export_step(14, 200);
  EXPECT_TRUE((chin(thrust, 1) - chin(thrust, 0)).isApprox(kForward * 200 * kFapu.mns, 1e-12));
}

TEST(BvhExport, JawAngleIsArcOverJawLength) {
  EXPECT_DOUBLE_EQ(jaw_angle_deg(0, kFapu.mns, 10.0), 0.0);
  EXPECT_NEAR(jaw_angle_deg(1024, 1.0 / 1024, 1.0), 180.0 / std::numbers::pi, 1e-12);
  EXPECT_LT(jaw_angle_deg(-100, kFapu.mns, 10.0), 0.0);  // negative values close past rest
}

TEST(BvhExport, AFaceWithoutALipPointIsRefusedByName) {
  FaceGeometry face = generic_adult_face();
  face.feature_points.erase({8, 7});
  FapSequence seq{"x", {25, 1}, {FapFrame{}}};
  try {
    fap_to_bvh(seq, face);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("8.7"), std::string::npos) << e.what();
  }
}

TEST(BvhExport, EmptySequenceGivesAHierarchyWithNoFrames) {
  const BvhDocument doc = fap_to_bvh(FapSequence{"empty", {25, 1}, {}}, kFace);
  EXPECT_EQ(doc.frame_count, 0u);
  EXPECT_EQ(read_bvh(write_bvh(doc), "empty.bvh"), doc);
}

}  // namespace
}  // namespace fapcast
