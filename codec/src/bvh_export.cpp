#include "fapcast/codec/bvh_export.hpp"

#include "fapcast/codec/fap_axis.hpp"

#include <array>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace fapcast {
namespace {

constexpr std::array<BvhRigPoint, 17> kRigPoints{{
    // Lower lip and tongue ride on the jaw: their FAPs displace them relative to it.
    {{2, 3}, true, "lip_2_3"},
    {{2, 8}, true, "lip_2_8"},
    {{2, 9}, true, "lip_2_9"},
    {{8, 2}, true, "lip_8_2"},
    {{8, 7}, true, "lip_8_7"},
    {{8, 8}, true, "lip_8_8"},
    {{6, 1}, true, "tongue_tip_6_1"},
    // Upper lip and the corners hang from the head.
    {{2, 2}, false, "lip_2_2"},
    {{2, 4}, false, "lip_2_4"},
    {{2, 5}, false, "lip_2_5"},
    {{2, 6}, false, "lip_2_6"},
    {{2, 7}, false, "lip_2_7"},
    {{8, 1}, false, "lip_8_1"},
    {{8, 3}, false, "lip_8_3"},
    {{8, 4}, false, "lip_8_4"},
    {{8, 5}, false, "lip_8_5"},
    {{8, 6}, false, "lip_8_6"},
}};

constexpr int kOpenJaw = 3, kThrustJaw = 14, kShiftJaw = 15;
constexpr int kHeadPitch = 48, kHeadYaw = 49, kHeadRoll = 50;

// One FAP's contribution to a rig point: displacement = value * step.
struct Drive {
  int fap;
  Eigen::Vector3d step;  // direction * FAPU, length units per FAP unit
};

// The FAPs that translate `fp` (from the FAP table's feature-point and direction columns).
std::vector<Drive> drives_of(FeaturePoint fp, const FapuValues& fapu) {
  std::vector<Drive> drives;
  for (const FapInfo& info : fap_table()) {
    if (info.feature_point != fp) continue;
    const auto axis = direction_axis(info.direction);
    if (axis) drives.push_back({info.number, *axis * fapu.of(info.unit)});
  }
  return drives;
}

double au_to_deg(std::int32_t value) { return value * kAngleUnitRad * 180.0 / std::numbers::pi; }

const std::vector<BvhChannel> kPositionRotation{BvhChannel::kXposition, BvhChannel::kYposition,
                                                 BvhChannel::kZposition, BvhChannel::kZrotation,
                                                 BvhChannel::kXrotation, BvhChannel::kYrotation};
const std::vector<BvhChannel> kPosition{BvhChannel::kXposition, BvhChannel::kYposition,
                                        BvhChannel::kZposition};

}  // namespace

std::span<const BvhRigPoint> bvh_rig_points() { return kRigPoints; }

double jaw_angle_deg(std::int32_t open_jaw, double mns, double jaw_length) {
  return open_jaw * mns / jaw_length * 180.0 / std::numbers::pi;
}

BvhDocument fap_to_bvh(const FapSequence& seq, const FaceGeometry& face) {
  if (!seq.rate.valid()) throw std::invalid_argument("BVH export: invalid frame rate");
  const FapuValues fapu = measure_fapu(face.feature_points);
  const double jaw_length = face.jaw_length();
  if (!(jaw_length > 0.0)) throw std::invalid_argument("BVH export: jaw pivot lies on the chin");

  BvhDocument doc;
  doc.frame_time_s = static_cast<double>(seq.rate.denominator) / seq.rate.numerator;
  doc.frame_count = seq.frames.size();
  doc.joints.push_back({std::string(kBvhHeadJoint), -1, face.head_pivot, kPositionRotation, {}});
  doc.joints.push_back({std::string(kBvhJawJoint), 0, face.jaw_pivot - face.head_pivot,
                        kPositionRotation, {}});
  // A short bone pointing forward gives each leaf a visible length (a tenth of the mouth width).
  const Eigen::Vector3d tip{0.0, 0.0, fapu.mw * 1024.0 / 10.0};
  std::vector<std::vector<Drive>> drives;
  for (const BvhRigPoint& p : kRigPoints) {
    const Eigen::Vector3d parent_origin = p.on_jaw ? face.jaw_pivot : face.head_pivot;
    doc.joints.push_back(
        {std::string(p.joint), p.on_jaw ? 1 : 0, face.at(p.fp) - parent_origin, kPosition, tip});
    drives.push_back(drives_of(p.fp, fapu));
  }

  const std::size_t width = doc.channel_count();
  doc.motion.reserve(seq.frames.size() * width);  // sized from our own data, not a file
  for (const FapFrame& f : seq.frames) {
    const Eigen::Vector3d& head = doc.joints[0].offset;
    doc.motion.insert(doc.motion.end(), {head.x(), head.y(), head.z(), au_to_deg(f.value(kHeadRoll)),
                                         au_to_deg(f.value(kHeadPitch)), au_to_deg(f.value(kHeadYaw))});
    // shift_jaw moves the chin to the face's right (-x), thrust_jaw forward (+z).
    const Eigen::Vector3d jaw = doc.joints[1].offset +
                                Eigen::Vector3d{-f.value(kShiftJaw) * fapu.mw, 0.0,
                                                f.value(kThrustJaw) * fapu.mns};
    doc.motion.insert(doc.motion.end(),
                      {jaw.x(), jaw.y(), jaw.z(), 0.0,
                       jaw_angle_deg(f.value(kOpenJaw), fapu.mns, jaw_length), 0.0});
    for (std::size_t i = 0; i < kRigPoints.size(); ++i) {
      Eigen::Vector3d at = doc.joints[i + 2].offset;
      for (const Drive& d : drives[i]) at += d.step * f.value(d.fap);
      doc.motion.insert(doc.motion.end(), {at.x(), at.y(), at.z()});
    }
  }
  return doc;
}

}  // namespace fapcast
