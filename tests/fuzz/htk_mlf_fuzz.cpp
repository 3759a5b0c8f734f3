// Fuzzes read_mlf (HTK master label files) and the pattern match: any input either reads or
// throws InputError.
#include "fapcast/corpus/htk_mlf.hpp"
#include "fapcast/core/input_error.hpp"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    for (const auto& e : fapcast::read_mlf(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz")) {
      (void)fapcast::mlf_pattern_matches(e.pattern, "sa1");
    }
  } catch (const fapcast::InputError&) {
  }
  return 0;
}
