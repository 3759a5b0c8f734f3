// libFuzzer: any bytes as an ICT-FaceKit folder's vertex_indices.json through
// load_ict_face_model, in a folder with a 4-vertex neutral mesh and two expression targets for it
// to name. Either InputError, or one target per expression name, each inside the mesh.
#include "fapcast/core/input_error.hpp"
#include "fapcast/face/face_model.hpp"
#include "fuzz/support/scratch_file.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  static const bool made = [] {
    fuzz::scratch_file("ict/generic_neutral_mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
    fuzz::scratch_file("ict/expressions/jawOpen.target", "# SYNTHETIC\n0 0 -1 0\n2 0 -0.5 0.25\n");
    fuzz::scratch_file("ict/expressions/mouthClose.target", "3 0.1 0 0\n");
    return true;
  }();
  (void)made;
  fuzz::scratch_file("ict/vertex_indices.json", {reinterpret_cast<const char*>(data), size});
  FaceModel model;
  try {
    model = load_ict_face_model(fuzz::scratch_dir() / "ict");
  } catch (const InputError&) {
    return 0;
  }
  if (model.expression_names.empty() || model.expressions.size() != model.expression_names.size()) std::abort();
  for (const SparseDelta& d : model.expressions)
    for (const std::int32_t v : d.vertices)
      if (v < 0 || v >= model.vertex_count()) std::abort();
  return 0;
}
