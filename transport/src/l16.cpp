#include "fapcast/transport/l16.hpp"

#include "fapcast/transport/rtp_packet.hpp"

#include <algorithm>

namespace fapcast {

std::size_t l16_frames_per_packet(SampleRate sample_rate, int channels, std::size_t overhead) {
  const std::size_t ten_ms = static_cast<std::size_t>(std::max<std::int64_t>(1, sample_rate.hz / 100));
  const std::size_t room = (kMaxDatagramBytes - kRtpFixedHeaderBytes - std::min<std::size_t>(overhead, 64)) /
                           (2 * static_cast<std::size_t>(std::max(1, channels)));
  return std::max<std::size_t>(1, std::min(ten_ms, room));
}

void pack_l16(std::span<const std::int16_t> interleaved, std::vector<std::uint8_t>& out) {
  out.reserve(out.size() + 2 * interleaved.size());
  for (const std::int16_t s : interleaved) {
    const auto u = static_cast<std::uint16_t>(s);
    out.push_back(static_cast<std::uint8_t>(u >> 8));
    out.push_back(static_cast<std::uint8_t>(u));
  }
}

std::vector<std::int16_t> unpack_l16(std::span<const std::uint8_t> payload) {
  std::vector<std::int16_t> out;
  out.reserve(payload.size() / 2);
  for (std::size_t i = 0; i + 1 < payload.size(); i += 2)
    out.push_back(static_cast<std::int16_t>((payload[i] << 8) | payload[i + 1]));
  return out;
}

}  // namespace fapcast
