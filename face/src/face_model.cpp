#include "fapcast/face/face_model.hpp"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "fapcast/core/data_file.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/data_root.hpp"

namespace fapcast {
namespace {

constexpr std::uintmax_t kMaxIndexFileBytes = 16u << 20;

}  // namespace

std::size_t FaceModel::expression_index(std::string_view name) const {
  for (std::size_t i = 0; i < expression_names.size(); ++i)
    if (expression_names[i] == name) return i;
  throw std::out_of_range("no ICT expression shape named '" + std::string(name) + "'");
}

FaceModel load_ict_face_model(const std::filesystem::path& folder) {
  FaceModel model;
  ObjMesh mesh = read_obj_mesh(folder / "generic_neutral_mesh.obj");
  model.neutral_cm = std::move(mesh.vertices);
  model.faces = std::move(mesh.faces);

  const auto index_file = folder / "vertex_indices.json";
  auto in = open_data_file(index_file, kMaxIndexFileBytes);
  nlohmann::json json;
  try {
    in >> json;
  } catch (const nlohmann::json::exception& e) {
    throw InputError::in_file(index_file.string(), 0, "bad-json", e.what());
  }
  const auto names = json.find("expressions");
  if (names == json.end() || !names->is_array() || names->empty())
    throw InputError::in_file(index_file.string(), 0, "no-expressions",
                        "needs an 'expressions' array of shape names");
  for (const auto& name : *names) {
    if (!name.is_string()) throw InputError::in_file(index_file.string(), 0, "bad-expression-name", name.dump());
    const auto s = name.get<std::string>();
    if (s.empty() || s.find_first_of("/\\.") != std::string::npos)
      throw InputError::in_file(index_file.string(), 0, "bad-expression-name", "'" + s + "'");
    model.expression_names.push_back(s);
    model.expressions.push_back(
        read_sparse_delta(folder / "expressions" / (s + ".target"), model.vertex_count()));
  }
  for (int i = 0;; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "identity%03d", i);
    const auto file = folder / "identities" / (std::string(name) + ".target");
    if (!std::filesystem::exists(file)) break;
    model.identity_names.emplace_back(name);
    model.identities.push_back(read_sparse_delta(file, model.vertex_count()));
  }
  return model;
}

const FaceModel& ict_face_model() {
  static const FaceModel model = load_ict_face_model(data_root() / "ict-facekit");
  return model;
}

FaceModel make_actor(const FaceModel& generic, std::span<const float> identity_weights) {
  if (identity_weights.size() > generic.identities.size())
    throw std::invalid_argument("make_actor: " + std::to_string(identity_weights.size()) +
                                " identity weights, model has " +
                                std::to_string(generic.identities.size()));
  FaceModel actor = generic;
  actor.neutral_cm = blend(generic.neutral_cm,
                           std::span(generic.identities).first(identity_weights.size()),
                           identity_weights);
  return actor;
}

}  // namespace fapcast
