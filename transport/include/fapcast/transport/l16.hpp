#pragma once
// L16 audio payload (RFC 3551 section 4.5.11): 16-bit signed samples, network byte order,
// channels interleaved per sampling instant.
#include "fapcast/core/sample_rate.hpp"
#include <cstdint>
#include <span>
#include <vector>

namespace fapcast {

// Sampling instants per L16 packet: 10 ms of audio, fewer when 10 ms of all channels would not
// fit in one datagram with `overhead` more bytes (SRTP's tag) (always >= 1). `channels` 1..255,
// `sample_rate` valid.
std::size_t l16_frames_per_packet(SampleRate sample_rate, int channels, std::size_t overhead = 0);

// Appends interleaved host-order samples in network byte order.
void pack_l16(std::span<const std::int16_t> interleaved, std::vector<std::uint8_t>& out);
// Decodes a payload into host-order samples (an odd trailing byte is ignored).
std::vector<std::int16_t> unpack_l16(std::span<const std::uint8_t> payload);

}  // namespace fapcast
