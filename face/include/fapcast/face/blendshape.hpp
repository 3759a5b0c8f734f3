#pragma once
// Sparse blendshapes: morph targets that move only some vertices, and blending them.
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "fapcast/face/mesh_types.hpp"

namespace fapcast {

// A morph target that moves only some vertices: offsets_cm.col(k) moves vertex vertices[k].
// Vertex indices are strictly increasing and < the mesh's vertex count.
struct SparseDelta {
  std::vector<std::int32_t> vertices;
  Positions offsets_cm;
};

// Reads a sparse target file: lines "vertex_index dx dy dz" ('#' comments), indices < vertex_count.
SparseDelta read_sparse_delta(const std::filesystem::path& file, std::int32_t vertex_count);

// base + sum_i weights[i] * deltas[i], touching only the vertices the deltas move.
Positions blend(const Positions& base, std::span<const SparseDelta> deltas,
                std::span<const float> weights);

// In place: mesh += weight * delta over the delta's vertices only.
void add_scaled(Positions& mesh, const SparseDelta& delta, float weight);

}  // namespace fapcast
