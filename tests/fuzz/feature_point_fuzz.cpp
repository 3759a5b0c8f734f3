// Fuzzes parse_feature_point (feature-point labels of marker files and face maps): any input
// parses or is refused, and what parses is a defined group and index whose label parses the same.
#include "fapcast/codec/feature_point.hpp"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const auto fp = parse_feature_point(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!fp) return 0;
  if (fp->group < 2 || fp->group > 11 || fp->index < 1 || fp->index > 99) __builtin_trap();
  if (parse_feature_point(fp->label()) != fp) __builtin_trap();
  return 0;
}
