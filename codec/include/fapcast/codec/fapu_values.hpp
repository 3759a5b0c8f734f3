#pragma once
// FAPU measured on a neutral face: the lengths one FAP unit stands for.
#include "fapcast/codec/feature_point.hpp"
#include "fapcast/codec/fapu.hpp"

#include <Eigen/Core>

#include <map>

namespace fapcast {

// Neutral positions of feature points, in the face's length unit (cm for the ICT face).
// Axes: x towards the face's own left, y up, z out of the face (towards the viewer).
using FeaturePointPositions = std::map<FeaturePoint, Eigen::Vector3d>;

// The length of one unit of each FAPU, in the length unit of the positions it was measured on.
struct FapuValues {
  double mns;    // (9.15.y - 2.2.y) / 1024: mouth-nose separation
  double mw;     // (8.3.x - 8.4.x) / 1024: mouth width
  double ens;    // (3.5.y - 9.15.y) / 1024: eye-nose separation
  double es;     // (3.5.x - 3.6.x) / 1024: eye separation
  double irisd;  // (3.1.y - 3.3.y) / 1024: iris diameter (upper to lower eyelid, neutral)

  // One unit of `unit` in length units; for kAU the angle unit in radians; 0 for kNone.
  double of(Fapu unit) const;

  bool operator==(const FapuValues&) const = default;
};

std::ostream& operator<<(std::ostream& out, const FapuValues& fapu);

// The feature points each FAPU is measured between.
inline constexpr FeaturePoint kFapuPoints[] = {{9, 15}, {2, 2}, {8, 3}, {8, 4},
                                               {3, 5},  {3, 6}, {3, 1}, {3, 3}};

// Measures the FAPU on a neutral face. Throws std::invalid_argument naming the feature point
// that is missing, or the unit whose defining distance is not positive (a face upside down or
// mirrored gives negative distances).
FapuValues measure_fapu(const FeaturePointPositions& neutral);

}  // namespace fapcast
