// Fuzzes read_esps_label (ESPS/xlabel/Festival): any input either reads or throws InputError.
#include "fapcast/corpus/esps_label.hpp"
#include "fapcast/core/input_error.hpp"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)fapcast::read_esps_label(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz", "phones");
  } catch (const fapcast::InputError&) {
  }
  return 0;
}
