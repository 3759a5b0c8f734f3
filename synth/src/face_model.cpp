#include "fapcast/synth/face_model.hpp"

#include <charconv>
#include <cstdio>
#include <cmath>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "fapcast/synth/data_file.hpp"
#include "fapcast/synth/data_file_error.hpp"
#include "fapcast/synth/data_root.hpp"

namespace fapcast::synth {
namespace {

// Hostile-input limits: far above ICT's 26,719 vertices, far below what would exhaust memory.
constexpr std::uintmax_t kMaxMeshBytes = 64u << 20;
constexpr std::int32_t kMaxVertices = 2'000'000;
constexpr std::size_t kMaxPolygonSides = 64;

// Splits on spaces and tabs.
std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

template <typename T>
bool parse(std::string_view text, T& value) {
  const auto [end, err] = std::from_chars(text.data(), text.data() + text.size(), value);
  return err == std::errc{} && end == text.data() + text.size();
}

float parse_coordinate(const std::filesystem::path& file, std::size_t line, std::string_view t) {
  float v = 0;
  if (!parse(t, v) || !std::isfinite(v))
    throw DataFileError(file.string(), line, "bad-coordinate", "'" + std::string(t) + "'");
  return v;
}

}  // namespace

std::size_t FaceModel::expression_index(std::string_view name) const {
  for (std::size_t i = 0; i < expression_names.size(); ++i)
    if (expression_names[i] == name) return i;
  throw std::out_of_range("no ICT expression shape named '" + std::string(name) + "'");
}

ObjMesh read_obj_mesh(const std::filesystem::path& file) {
  auto in = open_data_file(file, kMaxMeshBytes);
  std::vector<float> xyz;
  ObjMesh mesh;
  std::vector<std::pair<std::size_t, std::int64_t>> raw_faces;  // (line, index as written)
  std::string text;
  std::size_t line = 0;
  while (next_content_line(in, text, line)) {
    const auto t = tokens(text);
    if (t[0] == "v") {
      if (t.size() < 4)
        throw DataFileError(file.string(), line, "vertex-arity", "a v line needs x y z");
      if (xyz.size() / 3 >= static_cast<std::size_t>(kMaxVertices))
        throw DataFileError(file.string(), line, "too-many-vertices",
                            "more than " + std::to_string(kMaxVertices));
      for (int k = 1; k <= 3; ++k) xyz.push_back(parse_coordinate(file, line, t[k]));
    } else if (t[0] == "f") {
      if (t.size() < 4 || t.size() - 1 > kMaxPolygonSides)
        throw DataFileError(file.string(), line, "face-arity",
                            std::to_string(t.size() - 1) + " corners (3 to 64 allowed)");
      for (std::size_t k = 1; k < t.size(); ++k) {
        const auto corner = t[k].substr(0, t[k].find('/'));
        std::int64_t index = 0;
        if (!parse(corner, index) || index == 0)
          throw DataFileError(file.string(), line, "bad-face-index", "'" + std::string(t[k]) + "'");
        raw_faces.emplace_back(line, index);
      }
      mesh.faces.face_starts.push_back(static_cast<std::int32_t>(raw_faces.size()));
    }
    // vt, vn, g, o, s, usemtl, mtllib: not needed for geometry.
  }
  const auto n = static_cast<std::int64_t>(xyz.size() / 3);
  if (n == 0) throw DataFileError(file.string(), 0, "no-vertices", "no v lines");
  mesh.vertices = Eigen::Map<const Positions>(xyz.data(), 3, n);
  mesh.faces.face_vertices.reserve(raw_faces.size());
  for (const auto& [face_line, index] : raw_faces) {
    // OBJ: 1-based; negative counts back from the last vertex read (we resolve against all).
    const std::int64_t zero_based = index > 0 ? index - 1 : n + index;
    if (zero_based < 0 || zero_based >= n)
      throw DataFileError(file.string(), face_line, "face-index-out-of-range",
                          std::to_string(index) + " with " + std::to_string(n) + " vertices");
    mesh.faces.face_vertices.push_back(static_cast<std::int32_t>(zero_based));
  }
  return mesh;
}

SparseDelta read_sparse_delta(const std::filesystem::path& file, std::int32_t vertex_count) {
  auto in = open_data_file(file, kMaxMeshBytes);
  SparseDelta delta;
  std::vector<float> xyz;
  std::string text;
  std::size_t line = 0;
  while (next_content_line(in, text, line)) {
    const auto t = tokens(text);
    if (t.size() != 4)
      throw DataFileError(file.string(), line, "delta-arity",
                          "expected 'vertex_index dx dy dz', got " + std::to_string(t.size()) +
                              " fields");
    std::int64_t index = 0;
    if (!parse(t[0], index))
      throw DataFileError(file.string(), line, "bad-vertex-index", "'" + std::string(t[0]) + "'");
    if (index < 0 || index >= vertex_count)
      throw DataFileError(file.string(), line, "vertex-index-out-of-range",
                          std::to_string(index) + " not in [0, " + std::to_string(vertex_count) +
                              ")");
    if (!delta.vertices.empty() && index <= delta.vertices.back())
      throw DataFileError(file.string(), line, "vertex-index-not-increasing",
                          std::to_string(index) + " after " +
                              std::to_string(delta.vertices.back()));
    delta.vertices.push_back(static_cast<std::int32_t>(index));
    for (int k = 1; k <= 3; ++k) xyz.push_back(parse_coordinate(file, line, t[k]));
  }
  delta.offsets_cm =
      Eigen::Map<const Positions>(xyz.data(), 3, static_cast<Eigen::Index>(delta.vertices.size()));
  return delta;
}

FaceModel load_ict_face_model(const std::filesystem::path& folder) {
  FaceModel model;
  ObjMesh mesh = read_obj_mesh(folder / "generic_neutral_mesh.obj");
  model.neutral_cm = std::move(mesh.vertices);
  model.faces = std::move(mesh.faces);

  const auto index_file = folder / "vertex_indices.json";
  auto in = open_data_file(index_file, kMaxMeshBytes);
  nlohmann::json json;
  try {
    in >> json;
  } catch (const nlohmann::json::exception& e) {
    throw DataFileError(index_file.string(), 0, "bad-json", e.what());
  }
  const auto names = json.find("expressions");
  if (names == json.end() || !names->is_array() || names->empty())
    throw DataFileError(index_file.string(), 0, "no-expressions",
                        "needs an 'expressions' array of shape names");
  for (const auto& name : *names) {
    if (!name.is_string()) throw DataFileError(index_file.string(), 0, "bad-expression-name", name.dump());
    const auto s = name.get<std::string>();
    if (s.empty() || s.find_first_of("/\\.") != std::string::npos)
      throw DataFileError(index_file.string(), 0, "bad-expression-name", "'" + s + "'");
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

void add_scaled(Positions& mesh, const SparseDelta& delta, float weight) {
  if (weight == 0.0f) return;
  const auto* offsets = delta.offsets_cm.data();
  float* out = mesh.data();
  for (std::size_t k = 0; k < delta.vertices.size(); ++k) {
    float* v = out + 3 * static_cast<std::ptrdiff_t>(delta.vertices[k]);
    v[0] += weight * offsets[3 * k];
    v[1] += weight * offsets[3 * k + 1];
    v[2] += weight * offsets[3 * k + 2];
  }
}

Positions blend(const Positions& base, std::span<const SparseDelta> deltas,
                std::span<const float> weights) {
  if (weights.size() != deltas.size())
    throw std::invalid_argument("blend: " + std::to_string(weights.size()) + " weights for " +
                                std::to_string(deltas.size()) + " shapes");
  Positions mesh = base;
  for (std::size_t i = 0; i < deltas.size(); ++i) {
    if (!deltas[i].vertices.empty() && deltas[i].vertices.back() >= base.cols())
      throw std::invalid_argument("blend: shape " + std::to_string(i) + " moves vertex " +
                                  std::to_string(deltas[i].vertices.back()) + " of a " +
                                  std::to_string(base.cols()) + "-vertex mesh");
    add_scaled(mesh, deltas[i], weights[i]);
  }
  return mesh;
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

Eigen::Matrix3Xi triangulate(const PolygonFaces& faces) {
  std::size_t count = 0;
  for (std::size_t f = 0; f < faces.size(); ++f)
    count += static_cast<std::size_t>(faces.face_starts[f + 1] - faces.face_starts[f] - 2);
  Eigen::Matrix3Xi tris(3, static_cast<Eigen::Index>(count));
  Eigen::Index t = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto* v = faces.face_vertices.data() + faces.face_starts[f];
    const auto sides = faces.face_starts[f + 1] - faces.face_starts[f];
    for (std::int32_t k = 1; k + 1 < sides; ++k) tris.col(t++) << v[0], v[k], v[k + 1];
  }
  return tris;
}

}  // namespace fapcast::synth
