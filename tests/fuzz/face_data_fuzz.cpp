// Fuzzes the synth data readers (OBJ mesh, sparse delta target, spec TSV tables): any input must
// either parse or throw InputError - never crash, hang or allocate from a count in the file.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "fapcast/talker/articulation.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/marker_map.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("fapcast_face_data_fuzz_" + std::to_string(::getpid()));
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  using namespace fapcast;
  try { (void)read_obj_mesh(file); } catch (const InputError&) {}
  try { (void)read_sparse_delta(file, 1000); } catch (const InputError&) {}
  try { (void)read_marker_spec(file); } catch (const InputError&) {}
  try { (void)read_articulation_spec(file); } catch (const InputError&) {}
  try { (void)read_channel_shape_spec(file); } catch (const InputError&) {}
  return 0;
}
