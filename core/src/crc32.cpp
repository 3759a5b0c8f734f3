#include "fapcast/core/crc32.hpp"

#include <zlib.h>

namespace fapcast {

std::uint32_t crc32(std::span<const std::byte> bytes, std::uint32_t crc) {
  // zlib's crc32_z continues a previous result the same way (it applies the XORs itself), but
  // answers 0 for a null buffer: an empty span keeps the running value.
  if (bytes.empty()) return crc;
  return static_cast<std::uint32_t>(
      ::crc32_z(crc, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<z_size_t>(bytes.size())));
}

}  // namespace fapcast
