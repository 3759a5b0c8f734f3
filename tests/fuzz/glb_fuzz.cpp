// libFuzzer target for the .glb reader: any bytes either fail with InputError or give a mesh
// animation that writes and reads back to itself.
#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/core/input_error.hpp"

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  MorphAnimation a;
  try {
    a = read_glb(bytes, "fuzz.glb");
  } catch (const InputError&) {
    return 0;
  }
  std::string again;
  try {
    again = write_glb(a);
  } catch (const std::invalid_argument&) {
    return 0;  // readable but not writable, e.g. no triangles
  }
  const MorphAnimation b = read_glb(again, "rewritten.glb");
  if (b.base_positions_m != a.base_positions_m || b.triangles != a.triangles ||
      b.targets_m != a.targets_m || b.weights != a.weights || !(b.rate == a.rate))
    std::abort();
  return 0;
}
