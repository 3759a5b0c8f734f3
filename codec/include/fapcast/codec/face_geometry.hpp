#pragma once
// The face geometry an export needs besides the FAP values: neutral feature points and the two
// pivots (head, jaw) that no feature point marks. spec/bvh.md describes the default face.
#include "fapcast/codec/fapu_values.hpp"

#include <Eigen/Core>

namespace fapcast {

// A neutral face in one length unit (cm for the default face). Axes as FeaturePointPositions:
// x towards the face's own left, y up, z forward (out of the face, towards the viewer).
struct FaceGeometry {
  FeaturePointPositions feature_points;  // at least the FAPU points, 2.1, 2.2-2.9, 8.1-8.8, 6.1
  Eigen::Vector3d head_pivot{0, 0, 0};   // where head pitch/yaw/roll turn (top of the neck)
  Eigen::Vector3d jaw_pivot{0, 0, 0};    // the jaw's hinge (temporomandibular axis, midline)

  // The feature point `fp`; throws std::invalid_argument naming it when the face lacks it.
  const Eigen::Vector3d& at(FeaturePoint fp) const;
  // Jaw length: distance from the jaw pivot to the chin (2.1) in the y-z plane, length units.
  double jaw_length() const;
};

// A generic adult head (SYNTHETIC: round anthropometric figures, not a scan), in cm, origin at
// the head pivot. MNS = 2.2 cm, MW = 5.0 cm, ENS = 4.5 cm, ES = 6.4 cm, IRISD = 1.2 cm (all
// /1024 per unit), jaw length 11.86 cm. The synthesis stage passes the real target face instead.
FaceGeometry generic_adult_face();

// A face from measured neutral feature points (any length unit, face axes): the generic adult
// face scaled and moved onto them (least-squares uniform scale + translation over the points
// both have) supplies what they lack: the head and jaw pivots and any point the generic face
// has but `neutral` does not (e.g. the tongue tip 6.1 of a face captured without a tongue).
// Measured points are kept as given. Throws std::invalid_argument when fewer than two points
// are shared or they coincide.
FaceGeometry fit_generic_face(const FeaturePointPositions& neutral);

}  // namespace fapcast
