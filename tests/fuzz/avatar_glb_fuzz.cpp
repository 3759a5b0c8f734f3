// libFuzzer target for the avatar reader: any bytes either fail with InputError or give an avatar
// that, animated by ARKit and Oculus names, reads back as an avatar with the same morph targets.
#include "fapcast/core/input_error.hpp"
#include "fapcast/rig/arkit_shapes.hpp"
#include "fapcast/rig/avatar_glb.hpp"
#include "fapcast/rig/mouth_visemes.hpp"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  Avatar a;
  try {
    a = read_avatar(bytes, "fuzz.glb", {1u << 20, 100'000, 256});
  } catch (const InputError&) {
    return 0;
  }
  std::vector<std::string> names;
  for (const ArkitShape& s : kArkitShapes) names.emplace_back(s.name);
  for (std::string_view v : kOculusMorphNames) names.emplace_back(v);
  AvatarAnimation out;
  try {
    out = animate_avatar(a, names, Eigen::MatrixXf::Constant(3, static_cast<Eigen::Index>(names.size()), 0.5f), {60, 1}, "fuzz");
  } catch (const InputError&) {
    return 0;  // no target the rigs know
  }
  const Avatar b = read_avatar(out.bytes, "again.glb", {8u << 20, 100'000, 256});
  if (b.meshes.size() != a.meshes.size()) std::abort();
  for (std::size_t m = 0; m < a.meshes.size(); ++m)
    if (b.meshes[m].targets != a.meshes[m].targets) std::abort();
  return 0;
}
