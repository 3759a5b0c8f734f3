// Fuzzes read_timit_label (TIMIT .phn/.wrd): any input either reads or throws InputError.
#include "fapcast/corpus/timit_label.hpp"
#include "fapcast/core/input_error.hpp"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)fapcast::read_timit_label(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz", fapcast::SampleRate{16000}, "phones");
  } catch (const fapcast::InputError&) {
  }
  return 0;
}
