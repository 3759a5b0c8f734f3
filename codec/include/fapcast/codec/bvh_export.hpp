#pragma once
// FAP track -> BVH skeleton animation (spec/bvh.md): a head root turned by FAP 48-50, a jaw
// under it opened by FAP 3 and moved by FAP 14/15, and one position-animated joint per lip
// feature point (2.2-2.9, 8.1-8.8) and for the tongue tip (6.1), so the lip motion itself travels.
#include "fapcast/codec/bvh_document.hpp"
#include "fapcast/codec/face_geometry.hpp"
#include "fapcast/codec/fap_frame.hpp"

#include <span>
#include <string_view>

namespace fapcast {

inline constexpr std::string_view kBvhHeadJoint = "head";
inline constexpr std::string_view kBvhJawJoint = "jaw";

// A feature point the rig animates with Xposition Yposition Zposition channels.
struct BvhRigPoint {
  FeaturePoint fp;
  bool on_jaw;             // child of the jaw (lower lip, tongue tip) rather than of the head
  std::string_view joint;  // its joint name, e.g. "lip_2_2"
};

// The rig's feature-point joints in file order (jaw children first).
std::span<const BvhRigPoint> bvh_rig_points();

// The jaw rotation for an open_jaw value: the chin travels open_jaw * MNS along its arc around
// the jaw pivot, so the angle is open_jaw * MNS / face.jaw_length() radians (returned in
// degrees, positive = mouth opens, a positive Xrotation).
double jaw_angle_deg(std::int32_t open_jaw, double mns, double jaw_length);

// Builds the BVH for `seq` on `face` (its FAPU are measured from face.feature_points). Lengths
// are in the face's unit (cm for generic_adult_face()), rotations in degrees, Frame Time is the
// sequence's exact frame period. An unmasked FAP is at rest (0), as FapFrame stores it.
// Throws std::invalid_argument when the face lacks a point the rig or the FAPU need, or the
// sequence's rate is invalid.
BvhDocument fap_to_bvh(const FapSequence& seq, const FaceGeometry& face);

}  // namespace fapcast
