#pragma once
// The ICT-FaceKit blendshape face: neutral mesh, sparse expression and identity deltas, the actor.
// Coordinates: cm; x towards the face's own left, y up, z forward (out of the face).
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/face/blendshape.hpp"
#include "fapcast/face/mesh_types.hpp"
#include "fapcast/face/obj_mesh.hpp"

namespace fapcast {

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
// expressions/<name>.target, identities/identity*.target); throws InputError.
FaceModel load_ict_face_model(const std::filesystem::path& folder);

// The vendored ICT-FaceKit model at data_root()/ict-facekit, loaded once and shared.
const FaceModel& ict_face_model();

// The "actor": the generic neutral plus a mix of identity deltas (so it is not the target face);
// expression deltas are carried over unchanged. identity_weights.size() <= identities.size().
FaceModel make_actor(const FaceModel& generic, std::span<const float> identity_weights);

}  // namespace fapcast
