#pragma once
// Wavefront OBJ geometry: vertices and polygon faces (texture and normal indices are skipped).
#include <Eigen/Core>
#include <filesystem>

#include "fapcast/synth/mesh_types.hpp"

namespace fapcast::synth {

// An OBJ file's vertices (3 x N, file units) and faces (0-based).
struct ObjMesh {
  Positions vertices;
  PolygonFaces faces;
};
// Reads the v and f lines (1-based or negative indices) of an OBJ file; throws DataFileError.
ObjMesh read_obj_mesh(const std::filesystem::path& file);

// Splits every polygon into a fan of triangles: 3 x T vertex indices.
Eigen::Matrix3Xi triangulate(const PolygonFaces& faces);

}  // namespace fapcast::synth
