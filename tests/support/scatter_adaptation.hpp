#pragma once
// An independent implementation of the per-vertex adaptation maps (spec/adaptation.md) with no
// mesh structure: each triangle's map scattered onto its three corners, weighted by area. Used
// to cross-check FaceAdaptation (tests) and as the obvious alternative (benchmarks).
// Assumes no degenerate triangles and no isolated vertices (true of the ICT face).
#include <Eigen/Geometry>
#include <vector>

#include "fapcast/face/face_adaptation.hpp"
#include "fapcast/face/obj_mesh.hpp"

namespace fapcast::test {

inline std::vector<Eigen::Matrix3d> scatter_adaptation_maps(const Positions& generic,
                                                            const Positions& specific,
                                                            const PolygonFaces& faces) {
  const auto tris = triangulate(faces);
  std::vector<Eigen::Matrix3d> sum(static_cast<std::size_t>(generic.cols()), Eigen::Matrix3d::Zero());
  std::vector<double> weight(sum.size(), 0.0);
  const Eigen::Matrix3Xd x = generic.cast<double>(), y = specific.cast<double>();
  for (Eigen::Index t = 0; t < tris.cols(); ++t) {
    const int a = tris(0, t), b = tris(1, t), c = tris(2, t);
    const double area = 0.5 * (x.col(b) - x.col(a)).cross(x.col(c) - x.col(a)).norm();
    const Eigen::Matrix3d m =
        triangle_map(x.col(a), x.col(b), x.col(c), y.col(a), y.col(b), y.col(c));
    for (const int v : {a, b, c}) {
      sum[static_cast<std::size_t>(v)] += area * m;
      weight[static_cast<std::size_t>(v)] += area;
    }
  }
  for (std::size_t v = 0; v < sum.size(); ++v) sum[v] /= weight[v];
  return sum;
}

}  // namespace fapcast::test
