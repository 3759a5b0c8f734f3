#pragma once
// A user's avatar as glTF 2.0 binary (.glb) and an animation added to it (spec/rigs.md, "Avatars"):
// the morph targets are found by name (mesh.extras.targetNames, as three.js, Blender and Ready
// Player Me write them), one animation driving each named target the rig knows is appended, and
// every byte already in the file - meshes, materials, textures, skins, other animations - is kept:
// the JSON gains buffer views, accessors and the animation, the BIN chunk gains their data.
#include <Eigen/Core>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/core/frame_rate.hpp"

namespace fapcast {

struct AvatarLimits {
  std::uint64_t max_bytes = 256u << 20;       // the whole file
  std::uint64_t max_vertices = 4'000'000;     // summed over morphed primitives
  std::uint64_t max_targets_per_mesh = 1024;
};

struct AvatarMesh {
  int mesh = 0;                       // index into meshes
  std::string name;
  std::vector<std::string> targets;   // morph target names, in target order
  std::vector<float> default_weights; // mesh.weights, or zeros
  std::vector<int> nodes;             // nodes that instance the mesh
};

struct Avatar {
  std::string source;
  nlohmann::json json;
  std::vector<std::uint8_t> bin;      // the BIN chunk (buffer 0)
  std::vector<AvatarMesh> meshes;     // meshes with morph targets
};

// Reads and checks an avatar. InputError (source, byte offset where one applies) with rule
// glb-container, glb-syntax, avatar-too-large, avatar-no-morph-targets, avatar-unnamed-targets,
// gltf-accessor, gltf-indices, avatar-non-manifold (spec/rigs.md lists what each means).
Avatar read_avatar(std::string_view bytes, const std::string& source, const AvatarLimits& limits = {});

struct AvatarAnimation {
  std::string bytes;                  // the new .glb
  std::vector<std::string> driven;    // target names animated (sorted, unique)
  std::vector<std::string> unknown;   // target names the rig does not drive (kept at their default)
};

// Appends one animation named `name`: for each mesh, a weights channel on each of its nodes whose
// values are, per frame, `weights(f, j)` for a target named names[j] and the mesh's default weight
// for the others. Throws InputError `avatar-no-known-targets` (naming some expected names) when no
// target of the avatar is among `names`.
AvatarAnimation animate_avatar(const Avatar& avatar, std::span<const std::string> names, const Eigen::MatrixXf& weights,
                               FrameRate rate, const std::string& name);

}  // namespace fapcast
