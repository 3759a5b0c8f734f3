#include "fapcast/face/blendshape.hpp"

#include <stdexcept>
#include <string>

#include "fapcast/core/data_file.hpp"
#include "fapcast/core/input_error.hpp"

namespace fapcast {
namespace {

constexpr std::uintmax_t kMaxTargetBytes = 64u << 20;

}  // namespace

SparseDelta read_sparse_delta(const std::filesystem::path& file, std::int32_t vertex_count) {
  auto in = open_data_file(file, kMaxTargetBytes);
  SparseDelta delta;
  std::vector<float> xyz;
  std::string text;
  std::size_t line = 0;
  while (next_content_line(in, text, line)) {
    const auto t = split_whitespace(text);
    if (t.size() != 4)
      throw InputError::in_file(file.string(), line, "delta-arity",
                          "expected 'vertex_index dx dy dz', got " + std::to_string(t.size()) +
                              " fields");
    std::int64_t index = 0;
    if (!parse_number(t[0], index))
      throw InputError::in_file(file.string(), line, "bad-vertex-index", "'" + std::string(t[0]) + "'");
    if (index < 0 || index >= vertex_count)
      throw InputError::in_file(file.string(), line, "vertex-index-out-of-range",
                          std::to_string(index) + " not in [0, " + std::to_string(vertex_count) +
                              ")");
    if (!delta.vertices.empty() && index <= delta.vertices.back())
      throw InputError::in_file(file.string(), line, "vertex-index-not-increasing",
                          std::to_string(index) + " after " +
                              std::to_string(delta.vertices.back()));
    delta.vertices.push_back(static_cast<std::int32_t>(index));
    for (int k = 1; k <= 3; ++k) xyz.push_back(parse_coordinate(file, line, t[k]));
  }
  delta.offsets_cm =
      Eigen::Map<const Positions>(xyz.data(), 3, static_cast<Eigen::Index>(delta.vertices.size()));
  return delta;
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

}  // namespace fapcast
