// Fuzzes parse_expression_blend (`--expression` of say and animate): any input parses or is
// refused with std::invalid_argument, and what parses writes back as text that parses the same.
#include "fapcast/synthesis/speech_expression.hpp"

#include <cstdint>
#include <stdexcept>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  ExpressionBlend blend;
  try {
    blend = parse_expression_blend(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const std::invalid_argument&) {
    return 0;
  }
  if (parse_expression_blend(expression_blend_text(blend)) != blend) __builtin_trap();
  return 0;
}
