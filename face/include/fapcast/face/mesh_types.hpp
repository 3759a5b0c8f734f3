#pragma once
// Mesh value types: vertex positions (cm) and polygon faces.
// Coordinates: cm; x towards the face's own left, y up, z forward (out of the face).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace fapcast {

// 3 x N vertex positions (or displacements), cm.
using Positions = Eigen::Matrix3Xf;

// Polygon faces (ICT uses quads and a few triangles) in compressed rows: face f has the vertex
// indices face_vertices[face_starts[f] .. face_starts[f + 1]).
struct PolygonFaces {
  std::vector<std::int32_t> face_starts{0};
  std::vector<std::int32_t> face_vertices;
  std::size_t size() const { return face_starts.size() - 1; }
};

}  // namespace fapcast
