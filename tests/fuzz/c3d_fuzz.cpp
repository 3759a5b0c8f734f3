// Fuzzes the C3D reader; what it accepts and the writer can hold must read back with the same
// shape, labels and missing-sample mask.
#include "fapcast/corpus/c3d.hpp"
#include "fapcast/core/input_error.hpp"

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  C3dFile file;
  try {
    file = read_c3d(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const InputError&) {
    return 0;
  }
  std::string again;
  try {
    again = write_c3d(file.markers);
  } catch (const std::invalid_argument&) {
    return 0;  // e.g. a label with a NUL, or a rate that does not fit a float
  }
  const MarkerFrames<Millimetres> back = read_c3d(again, "again").markers;
  if (back.labels != file.markers.labels || back.frame_count() != file.markers.frame_count() ||
      back.positions.array().isNaN().matrix() != file.markers.positions.array().isNaN().matrix()) {
    std::abort();
  }
  return 0;
}
