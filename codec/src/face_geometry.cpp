#include "fapcast/codec/face_geometry.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace fapcast {

const Eigen::Vector3d& FaceGeometry::at(FeaturePoint fp) const {
  const auto it = feature_points.find(fp);
  if (it == feature_points.end())
    throw std::invalid_argument("face geometry: feature point " + fp.label() + " is missing");
  return it->second;
}

double FaceGeometry::jaw_length() const {
  const Eigen::Vector3d arm = at({2, 1}) - jaw_pivot;
  return std::hypot(arm.y(), arm.z());
}

FaceGeometry generic_adult_face() {
  // One row per feature point: label, x (face's left), y (up), z (forward), cm from the head
  // pivot. Round figures for an adult: pupils 6.4 cm apart, mouth 5 cm wide, subnasale 2.2 cm
  // above the lips' meeting line, chin 12 cm along the mandible from its hinge.
  struct Row {
    FeaturePoint fp;
    double x, y, z;
  };
  static constexpr Row kRows[] = {
      {{2, 1}, 0.0, -7.6, 9.6},     // chin, bottom middle (gnathion)
      {{2, 2}, 0.0, -2.7, 10.6},    // upper inner lip, middle
      {{2, 3}, 0.0, -2.7, 10.5},    // lower inner lip, middle (lips closed at rest)
      {{2, 4}, 2.3, -2.7, 9.4},     // inner lip corner, left
      {{2, 5}, -2.3, -2.7, 9.4},    // inner lip corner, right
      {{2, 6}, 1.2, -2.65, 10.3},   // upper inner lip, left of middle
      {{2, 7}, -1.2, -2.65, 10.3},  // upper inner lip, right of middle
      {{2, 8}, 1.2, -2.75, 10.2},   // lower inner lip, left of middle
      {{2, 9}, -1.2, -2.75, 10.2},  // lower inner lip, right of middle
      {{3, 1}, 3.2, 4.6, 9.0},      // left upper eyelid, middle
      {{3, 2}, -3.2, 4.6, 9.0},     // right upper eyelid, middle
      {{3, 3}, 3.2, 3.4, 9.0},      // left lower eyelid, middle (IRISD 1.2 cm)
      {{3, 4}, -3.2, 3.4, 9.0},     // right lower eyelid, middle
      {{3, 5}, 3.2, 4.0, 8.5},      // left pupil
      {{3, 6}, -3.2, 4.0, 8.5},     // right pupil
      {{6, 1}, 0.0, -2.9, 9.6},     // tongue tip, behind the inner lips
      {{8, 1}, 0.0, -2.0, 11.0},    // upper outer lip, middle
      {{8, 2}, 0.0, -3.6, 10.8},    // lower outer lip, middle
      {{8, 3}, 2.5, -2.7, 9.3},     // outer lip corner, left
      {{8, 4}, -2.5, -2.7, 9.3},    // outer lip corner, right
      {{8, 5}, 1.3, -2.1, 10.6},    // upper outer lip, left of middle
      {{8, 6}, -1.3, -2.1, 10.6},   // upper outer lip, right of middle
      {{8, 7}, 1.3, -3.5, 10.4},    // lower outer lip, left of middle
      {{8, 8}, -1.3, -3.5, 10.4},   // lower outer lip, right of middle
      {{9, 15}, 0.0, -0.5, 11.0},   // nose, bottom middle (subnasale)
  };
  FaceGeometry face;
  for (const Row& r : kRows) face.feature_points[r.fp] = Eigen::Vector3d{r.x, r.y, r.z};
  face.head_pivot = Eigen::Vector3d{0.0, 0.0, 0.0};
  face.jaw_pivot = Eigen::Vector3d{0.0, 1.5, 2.0};  // condyles: 1.5 cm up, 2 cm forward
  return face;
}

FaceGeometry fit_generic_face(const FeaturePointPositions& neutral) {
  const FaceGeometry generic = generic_adult_face();
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> pairs;  // (generic, measured)
  for (const auto& [fp, at] : generic.feature_points)
    if (const auto it = neutral.find(fp); it != neutral.end()) pairs.emplace_back(at, it->second);
  if (pairs.size() < 2) throw std::invalid_argument("face fit: fewer than two feature points in common with the generic face");
  Eigen::Vector3d cg = Eigen::Vector3d::Zero(), cm = Eigen::Vector3d::Zero();
  for (const auto& [g, m] : pairs) cg += g, cm += m;
  cg /= static_cast<double>(pairs.size());
  cm /= static_cast<double>(pairs.size());
  double gg = 0.0, gm = 0.0;
  for (const auto& [g, m] : pairs) gg += (g - cg).squaredNorm(), gm += (g - cg).dot(m - cm);
  if (!(gg > 0.0) || !(gm > 0.0)) throw std::invalid_argument("face fit: the shared feature points coincide or are mirrored");
  const double s = gm / gg;  // least-squares scale (no rotation: both use face axes)
  auto place = [&](const Eigen::Vector3d& g) -> Eigen::Vector3d { return cm + s * (g - cg); };
  FaceGeometry face;
  for (const auto& [fp, at] : generic.feature_points) face.feature_points[fp] = place(at);
  for (const auto& [fp, at] : neutral) face.feature_points[fp] = at;
  face.head_pivot = place(generic.head_pivot);
  face.jaw_pivot = place(generic.jaw_pivot);
  return face;
}

}  // namespace fapcast
