#pragma once
// Mesh animation as glTF 2.0 binary (.glb, spec/gltf.md): one mesh whose morph targets are
// driven by one animation of their weights. Knows nothing of synthesis: a voice's PCA mean is the
// base mesh, its components the morph targets and its PCA frames the weights.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/frame_rate.hpp"

namespace fapcast {

// glTF units and axes: metres, +y up, +z towards the viewer (the face's front), right-handed.
struct MorphAnimation {
  std::string name;                           // mesh, node and animation name (may be empty)
  Eigen::Matrix3Xf base_positions_m;          // 3 x N neutral vertex positions
  Eigen::Matrix3Xi triangles;                 // 3 x T vertex indices, 0-based, counter-clockwise
  std::optional<Eigen::Matrix3Xf> normals;    // 3 x N unit normals of the base mesh, optional
  std::vector<Eigen::Matrix3Xf> targets_m;    // K morph targets: 3 x N displacements each
  std::vector<std::string> target_names;      // empty or K names (mesh.extras.targetNames)
  Eigen::MatrixXf weights;                    // F x K: frame f's weight of target k
  FrameRate rate{60, 1};                      // frame f is shown at f * denominator / numerator s
};

// The animation's vertex positions at frame f: base + sum_k weights(f, k) * targets_m[k].
Eigen::Matrix3Xf frame_positions(const MorphAnimation& animation, Eigen::Index frame);

// The .glb bytes: one scene, one node, one mesh with one triangle primitive (POSITION, optional
// NORMAL, uint32 indices, K POSITION targets, every POSITION accessor with min/max) and, when
// F >= 1 and K >= 1, one animation with one LINEAR sampler whose input holds the F key times
// (f * denominator / numerator seconds) and output the F x K weights, frame-major.
// Throws std::invalid_argument when the shapes disagree, an index is out of range, a value is not
// finite, or the rate is invalid.
std::string write_glb(const MorphAnimation& animation);

// Reads a .glb in the shape write_glb writes (one mesh, one triangle primitive, float POSITION
// targets, at most one weights animation sampled at a constant rate). Throws InputError
// (source, byte offset when known, rule) for anything else. The rate is recovered from the key
// times as the nearest integer frames per second.
MorphAnimation read_glb(std::string_view bytes, const std::string& source);

}  // namespace fapcast
