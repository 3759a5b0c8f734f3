#include "fapcast/core/crc32.hpp"

#include <libdeflate.h>

namespace fapcast {

std::uint32_t crc32(std::span<const std::byte> bytes, std::uint32_t crc) {
  // libdeflate_crc32 continues a previous result the same way zlib's crc32_z does (it applies
  // the XORs itself); an empty span keeps the running value.
  if (bytes.empty()) return crc;
  return libdeflate_crc32(crc, bytes.data(), bytes.size());
}

}  // namespace fapcast
