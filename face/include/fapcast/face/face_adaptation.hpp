#pragma once
// Model adaptation (paper section 3.9): motion designed on a generic face, transferred to a
// specific face of the same topology. Each triangle gets the linear map that carries its generic
// shape onto its specific shape; each vertex the area-weighted mean of its triangles' maps; an
// adapted displacement is that vertex's map times the generic displacement (spec/adaptation.md).
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fapcast/face/blendshape.hpp"
#include "fapcast/face/mesh_types.hpp"

namespace fapcast {

class FaceAdaptation {
 public:
  // generic, specific: 3 x N vertex positions of the two models in one unit (cm for ICT);
  // faces: their shared polygon faces (polygons are split into fans of triangles).
  // Throws std::invalid_argument when the vertex counts differ, a face index is out of range,
  // or the faces are not an oriented 2-manifold (OpenMesh refuses the triangle; the message
  // names it).
  FaceAdaptation(const Positions& generic, const Positions& specific, const PolygonFaces& faces);

  // 3 x N generic displacements -> 3 x N displacements for the specific face (same unit).
  // Throws std::invalid_argument when the column count is not vertex_count().
  Positions adapt(const Positions& generic_displacements) const;
  // The same for a sparse morph target: the same vertices, each offset mapped.
  SparseDelta adapt(const SparseDelta& generic_delta) const;

  std::int32_t vertex_count() const { return static_cast<std::int32_t>(maps_.size()); }
  // Vertex i's map: specific displacement = vertex_map(i) * generic displacement.
  const Eigen::Matrix3f& vertex_map(std::int32_t i) const { return maps_[static_cast<std::size_t>(i)]; }
  // Least-squares linear map from generic to specific positions about their centroids; the map
  // of every vertex that touches no usable triangle.
  const Eigen::Matrix3d& global_map() const { return global_map_; }

  std::size_t triangle_count() const { return triangle_count_; }
  // Triangles whose generic area is (numerically) zero: they get weight 0.
  std::size_t degenerate_triangle_count() const { return degenerate_triangle_count_; }
  // Vertices with no non-degenerate triangle: they take global_map().
  std::size_t global_map_vertex_count() const { return global_map_vertex_count_; }
  // Heap bytes held (the per-vertex maps).
  std::size_t memory_bytes() const { return maps_.capacity() * sizeof(Eigen::Matrix3f); }

 private:
  std::vector<Eigen::Matrix3f> maps_;
  Eigen::Matrix3d global_map_ = Eigen::Matrix3d::Identity();
  std::size_t triangle_count_ = 0;
  std::size_t degenerate_triangle_count_ = 0;
  std::size_t global_map_vertex_count_ = 0;
};

// The map of one triangle: A with A (x2 - x1) = y2 - y1, A (x3 - x1) = y3 - y1 and
// A n_x / sqrt|n_x| = n_y / sqrt|n_y| (n = the unnormalised face normal), i.e. deformation
// transfer's frame. Exact for any similarity; needs a non-degenerate generic triangle.
Eigen::Matrix3d triangle_map(const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                             const Eigen::Vector3d& x3, const Eigen::Vector3d& y1,
                             const Eigen::Vector3d& y2, const Eigen::Vector3d& y3);

}  // namespace fapcast
