// Fuzzes read_ema: any input either reads or throws InputError, never crashes or over-allocates.
#include "fapcast/corpus/ema.hpp"
#include "fapcast/core/input_error.hpp"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)fapcast::read_ema(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const fapcast::InputError&) {
  }
  return 0;
}
