#include "fapcast/codec/bvh_document.hpp"

#include <array>
#include <cctype>
#include <numbers>

namespace fapcast {
namespace {
constexpr std::array<std::string_view, 6> kChannelNames = {
    "Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation"};

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}
}  // namespace

std::string_view to_string(BvhChannel channel) {
  return kChannelNames[static_cast<std::size_t>(channel)];
}

std::ostream& operator<<(std::ostream& out, BvhChannel channel) { return out << to_string(channel); }

std::optional<BvhChannel> parse_bvh_channel(std::string_view name) {
  for (std::size_t i = 0; i < kChannelNames.size(); ++i)
    if (equal_ignoring_case(name, kChannelNames[i])) return static_cast<BvhChannel>(i);
  return std::nullopt;
}

std::size_t BvhDocument::channel_count() const {
  std::size_t n = 0;
  for (const BvhJoint& j : joints) n += j.channels.size();
  return n;
}

std::span<const double> BvhDocument::frame(std::uint64_t k) const {
  const std::size_t n = channel_count();
  return std::span<const double>(motion).subspan(static_cast<std::size_t>(k) * n, n);
}

std::optional<std::size_t> BvhDocument::find_joint(std::string_view name) const {
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == name) return i;
  return std::nullopt;
}

std::ostream& operator<<(std::ostream& out, const BvhDocument& doc) {
  out << "BVH{" << doc.joints.size() << " joints, " << doc.frame_count << " frames of "
      << doc.frame_time_s << " s";
  for (const BvhJoint& j : doc.joints) {
    out << "; " << j.name << " (parent " << j.parent << ", offset " << j.offset.transpose()
        << ",";
    for (BvhChannel c : j.channels) out << ' ' << c;
    out << ')';
  }
  return out << '}';
}

std::vector<Eigen::Affine3d> joint_world_transforms(const BvhDocument& doc, std::uint64_t k) {
  const std::span<const double> values = doc.frame(k);
  std::vector<Eigen::Affine3d> world;
  world.reserve(doc.joints.size());
  std::size_t next = 0;
  for (const BvhJoint& joint : doc.joints) {
    Eigen::Vector3d translation = joint.offset;
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    for (BvhChannel c : joint.channels) {
      const double v = values[next++];
      const auto axis = static_cast<int>(c) % 3;  // 0 = X, 1 = Y, 2 = Z
      if (static_cast<int>(c) < 3) {
        translation[axis] = v;
      } else {
        rotation = rotation * Eigen::AngleAxisd(v * std::numbers::pi / 180.0,
                                                Eigen::Vector3d::Unit(axis))
                                  .toRotationMatrix();
      }
    }
    Eigen::Affine3d local = Eigen::Affine3d::Identity();
    local.translate(translation).rotate(rotation);
    world.push_back(joint.parent < 0 ? local
                                     : world[static_cast<std::size_t>(joint.parent)] * local);
  }
  return world;
}

}  // namespace fapcast
