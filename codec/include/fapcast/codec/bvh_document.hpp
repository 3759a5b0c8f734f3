#pragma once
// A BVH (Biovision hierarchy) motion file in memory: a joint hierarchy with channels, and one row
// of channel values per frame. bvh_text.hpp reads and writes it; spec/bvh.md describes the rig
// fapcast exports.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

// One animated degree of freedom. Positions in the file's length unit, rotations in degrees.
enum class BvhChannel : std::uint8_t { kXposition, kYposition, kZposition, kXrotation, kYrotation, kZrotation };

std::string_view to_string(BvhChannel channel);  // "Xposition", ... as BVH spells them
std::ostream& operator<<(std::ostream& out, BvhChannel channel);
// Parses a channel name, ignoring case as importers do ("xrotation" == "Xrotation").
std::optional<BvhChannel> parse_bvh_channel(std::string_view name);

struct BvhJoint {
  std::string name;                         // no whitespace; unique in the document
  int parent = -1;                          // index of the parent joint; -1 for the root
  Eigen::Vector3d offset{0, 0, 0};          // rest position relative to the parent's origin
  std::vector<BvhChannel> channels;         // in file order; rotations compose in this order
  std::optional<Eigen::Vector3d> end_site;  // End Site offset of a leaf, if written

  bool operator==(const BvhJoint&) const = default;
};

struct BvhDocument {
  std::vector<BvhJoint> joints;  // depth-first, as in the file; joints[0] is the root
  double frame_time_s = 0.04;    // "Frame Time:", seconds per frame
  std::uint64_t frame_count = 0; // "Frames:"
  std::vector<double> motion;    // frame_count rows of channel_count() values, row after row

  // Sum of the joints' channel counts: the number of values on each motion line.
  std::size_t channel_count() const;
  // The values of frame k (0 <= k < frame_count), in depth-first channel order.
  std::span<const double> frame(std::uint64_t k) const;
  // Index of the joint named `name`, or nullopt.
  std::optional<std::size_t> find_joint(std::string_view name) const;

  bool operator==(const BvhDocument&) const = default;
};

// Prints the hierarchy in one line per joint, for test failure messages.
std::ostream& operator<<(std::ostream& out, const BvhDocument& doc);

// Each joint's transform to the root's parent space at frame k (0 <= k < frame_count), with the
// semantics Blender's importer uses: a position channel replaces that component of the joint's
// OFFSET (so at rest it equals the OFFSET), and the rotation channels compose in file order
// (CHANNELS ... Zrotation Xrotation Yrotation gives R = Rz * Rx * Ry). Index i is joints[i].
std::vector<Eigen::Affine3d> joint_world_transforms(const BvhDocument& doc, std::uint64_t k);

}  // namespace fapcast
