// Fuzzes unpack_l16 (received L16 audio payloads): every payload decodes to one sample per two
// bytes (an odd trailing byte ignored), and packing the samples gives those bytes back.
#include "fapcast/transport/l16.hpp"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const std::span<const std::uint8_t> payload(data, size);
  const std::vector<std::int16_t> samples = unpack_l16(payload);
  if (samples.size() != size / 2) __builtin_trap();
  std::vector<std::uint8_t> again;
  pack_l16(samples, again);
  if (!std::equal(again.begin(), again.end(), payload.begin(), payload.begin() + static_cast<std::ptrdiff_t>(size / 2 * 2)) ||
      again.size() != size / 2 * 2)
    __builtin_trap();
  return 0;
}
