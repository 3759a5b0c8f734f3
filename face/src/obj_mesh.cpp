#include "fapcast/face/obj_mesh.hpp"

#include <array>
#include <charconv>
#include <string>
#include <utility>
#include <vector>

#include "fapcast/core/data_file.hpp"
#include "fapcast/core/input_error.hpp"

namespace fapcast {
namespace {

// Hostile-input limits: far above ICT's 26,719 vertices, far below what would exhaust memory.
constexpr std::uintmax_t kMaxMeshBytes = 64u << 20;
constexpr std::int32_t kMaxVertices = 2'000'000;
constexpr std::size_t kMaxPolygonSides = 64;

}  // namespace

ObjMesh read_obj_mesh(const std::filesystem::path& file) {
  auto in = open_data_file(file, kMaxMeshBytes);
  std::vector<float> xyz;
  ObjMesh mesh;
  std::vector<std::pair<std::size_t, std::int64_t>> raw_faces;  // (line, index as written)
  std::string text;
  std::size_t line = 0;
  while (next_content_line(in, text, line)) {
    const auto t = split_whitespace(text);
    if (t[0] == "v") {
      if (t.size() < 4)
        throw InputError::in_file(file.string(), line, "vertex-arity", "a v line needs x y z");
      if (xyz.size() / 3 >= static_cast<std::size_t>(kMaxVertices))
        throw InputError::in_file(file.string(), line, "too-many-vertices",
                            "more than " + std::to_string(kMaxVertices));
      for (int k = 1; k <= 3; ++k) xyz.push_back(parse_coordinate(file, line, t[k]));
    } else if (t[0] == "f") {
      if (t.size() < 4 || t.size() - 1 > kMaxPolygonSides)
        throw InputError::in_file(file.string(), line, "face-arity",
                            std::to_string(t.size() - 1) + " corners (3 to 64 allowed)");
      for (std::size_t k = 1; k < t.size(); ++k) {
        const auto corner = t[k].substr(0, t[k].find('/'));
        std::int64_t index = 0;
        if (!parse_number(corner, index) || index == 0)
          throw InputError::in_file(file.string(), line, "bad-face-index", "'" + std::string(t[k]) + "'");
        raw_faces.emplace_back(line, index);
      }
      mesh.faces.face_starts.push_back(static_cast<std::int32_t>(raw_faces.size()));
    }
    // vt, vn, g, o, s, usemtl, mtllib: not needed for geometry.
  }
  const auto n = static_cast<std::int64_t>(xyz.size() / 3);
  if (n == 0) throw InputError::in_file(file.string(), 0, "no-vertices", "no v lines");
  mesh.vertices = Eigen::Map<const Positions>(xyz.data(), 3, n);
  mesh.faces.face_vertices.reserve(raw_faces.size());
  for (const auto& [face_line, index] : raw_faces) {
    // OBJ: 1-based; negative counts back from the last vertex read (we resolve against all).
    const std::int64_t zero_based = index > 0 ? index - 1 : n + index;
    if (zero_based < 0 || zero_based >= n)
      throw InputError::in_file(file.string(), face_line, "face-index-out-of-range",
                          std::to_string(index) + " with " + std::to_string(n) + " vertices");
    mesh.faces.face_vertices.push_back(static_cast<std::int32_t>(zero_based));
  }
  return mesh;
}

std::string write_obj_mesh(const Positions& vertices, const PolygonFaces& faces,
                           std::string_view comment) {
  std::string out;
  out.reserve(static_cast<std::size_t>(vertices.cols()) * 40 + faces.face_vertices.size() * 8);
  if (!comment.empty()) {
    out += "# ";
    out += comment;
    out += '\n';
  }
  std::array<char, 32> buffer{};
  for (Eigen::Index i = 0; i < vertices.cols(); ++i) {
    out += 'v';
    for (int c = 0; c < 3; ++c) {
      // Shortest text that reads back to the same float: OBJ round trips are exact.
      const auto r = std::to_chars(buffer.data(), buffer.data() + buffer.size(), vertices(c, i));
      out += ' ';
      out.append(buffer.data(), r.ptr);
    }
    out += '\n';
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    out += 'f';
    for (auto k = faces.face_starts[f]; k < faces.face_starts[f + 1]; ++k) {
      out += ' ';
      out += std::to_string(faces.face_vertices[static_cast<std::size_t>(k)] + 1);
    }
    out += '\n';
  }
  return out;
}

void require_same_topology(const ObjMesh& generic, const std::filesystem::path& generic_file,
                           const ObjMesh& specific, const std::filesystem::path& specific_file) {
  const auto mismatch = [&](const std::string& what) {
    std::string detail = what;
    detail += " (generic mesh ";
    detail += generic_file.string();
    detail += ")";
    throw InputError::in_file(specific_file.string(), 0, "topology-mismatch", detail);
  };
  if (specific.vertices.cols() != generic.vertices.cols())
    mismatch(std::to_string(specific.vertices.cols()) + " vertices, expected " +
             std::to_string(generic.vertices.cols()));
  if (specific.faces.size() != generic.faces.size())
    mismatch(std::to_string(specific.faces.size()) + " faces, expected " +
             std::to_string(generic.faces.size()));
  for (std::size_t f = 0; f < generic.faces.size(); ++f) {
    const auto begin = generic.faces.face_starts[f], end = generic.faces.face_starts[f + 1];
    bool same = specific.faces.face_starts[f] == begin && specific.faces.face_starts[f + 1] == end;
    for (auto k = begin; same && k < end; ++k)
      same = specific.faces.face_vertices[static_cast<std::size_t>(k)] ==
             generic.faces.face_vertices[static_cast<std::size_t>(k)];
    if (!same) mismatch("face " + std::to_string(f + 1) + " has other corners than the generic mesh's");
  }
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

}  // namespace fapcast
