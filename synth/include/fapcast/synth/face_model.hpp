#pragma once
// The ICT-FaceKit blendshape face: neutral mesh, sparse expression and identity deltas, blending.
// Coordinates: cm; x towards the face's own left, y up, z forward (out of the face).
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast::synth {

// 3 x N vertex positions (or displacements), cm.
using Positions = Eigen::Matrix3Xf;

// A morph target that moves only some vertices: offsets_cm.col(k) moves vertex vertices[k].
// Vertex indices are strictly increasing and < the mesh's vertex count.
struct SparseDelta {
  std::vector<std::int32_t> vertices;
  Positions offsets_cm;
};

// Polygon faces (ICT uses quads and a few triangles) in compressed rows: face f has the vertex
// indices face_vertices[face_starts[f] .. face_starts[f + 1]).
struct PolygonFaces {
  std::vector<std::int32_t> face_starts{0};
  std::vector<std::int32_t> face_vertices;
  std::size_t size() const { return face_starts.size() - 1; }
};

struct FaceModel {
  Positions neutral_cm;                       // 3 x N
  PolygonFaces faces;                         // as in the OBJ file, 0-based
  std::vector<std::string> expression_names;  // 53 ICT expression shapes, in ICT's order
  std::vector<SparseDelta> expressions;       // one per name
  std::vector<std::string> identity_names;    // identity000 ... identity009
  std::vector<SparseDelta> identities;

  std::int32_t vertex_count() const { return static_cast<std::int32_t>(neutral_cm.cols()); }
  // Index of an expression shape by its ICT name; throws std::out_of_range naming it.
  std::size_t expression_index(std::string_view name) const;
};

// Loads the ICT-FaceKit folder (generic_neutral_mesh.obj, vertex_indices.json,
// expressions/<name>.target, identities/identity*.target); throws DataFileError.
FaceModel load_ict_face_model(const std::filesystem::path& folder);

// The vendored ICT-FaceKit model at data_root()/ict-facekit, loaded once and shared.
const FaceModel& ict_face_model();

// Reads the vertices (v lines) and faces (f lines, 1-based or negative indices) of an OBJ mesh.
struct ObjMesh {
  Positions vertices;
  PolygonFaces faces;
};
ObjMesh read_obj_mesh(const std::filesystem::path& file);

// Reads a sparse target file: lines "vertex_index dx dy dz" ('#' comments), indices < vertex_count.
SparseDelta read_sparse_delta(const std::filesystem::path& file, std::int32_t vertex_count);

// base + sum_i weights[i] * deltas[i], touching only the vertices the deltas move.
Positions blend(const Positions& base, std::span<const SparseDelta> deltas,
                std::span<const float> weights);

// In place: mesh += weight * delta over the delta's vertices only.
void add_scaled(Positions& mesh, const SparseDelta& delta, float weight);

// The "actor": the generic neutral plus a mix of identity deltas (so it is not the target face);
// expression deltas are carried over unchanged. identity_weights.size() <= identities.size().
FaceModel make_actor(const FaceModel& generic, std::span<const float> identity_weights);

// Splits every polygon into a fan of triangles: 3 x T vertex indices.
Eigen::Matrix3Xi triangulate(const PolygonFaces& faces);

}  // namespace fapcast::synth
