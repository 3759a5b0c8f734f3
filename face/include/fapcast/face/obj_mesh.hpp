#pragma once
// Wavefront OBJ geometry: vertices and polygon faces (texture and normal indices are skipped).
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <string_view>

#include "fapcast/core/input_error.hpp"
#include "fapcast/face/mesh_types.hpp"

namespace fapcast {

// An OBJ file's vertices (3 x N, file units) and faces (0-based).
struct ObjMesh {
  Positions vertices;
  PolygonFaces faces;
};
// Reads the v and f lines (1-based or negative indices) of an OBJ file; throws InputError.
ObjMesh read_obj_mesh(const std::filesystem::path& file);

// The OBJ text of a mesh: "v x y z" lines (shortest round-trip float text), then "f" lines
// (1-based), with an optional leading "# comment" line.
std::string write_obj_mesh(const Positions& vertices, const PolygonFaces& faces,
                           std::string_view comment = {});

// Throws InputError(specific_file, 0, "topology-mismatch") when `specific` does not have the
// vertex count and the faces (same corners, same order) of `generic`, naming the first difference.
void require_same_topology(const ObjMesh& generic, const std::filesystem::path& generic_file,
                           const ObjMesh& specific, const std::filesystem::path& specific_file);

// Splits every polygon into a fan of triangles: 3 x T vertex indices.
Eigen::Matrix3Xi triangulate(const PolygonFaces& faces);

}  // namespace fapcast
