#include "fapcast/transport/rtp_packet.hpp"

#include "fapcast/transport/byte_order.hpp"
#include "fapcast/transport/rtp_error.hpp"

namespace fapcast {

std::size_t rtp_header_bytes(const RtpHeader& header) {
  return kRtpFixedHeaderBytes + 4u * (header.csrc_count & 0x0f);
}

std::error_code parse_rtp(std::span<const std::uint8_t> d, RtpPacketView& out) {
  if (d.size() < kRtpFixedHeaderBytes) return RtpErrc::kTruncatedHeader;
  const std::uint8_t b0 = d[0];
  const std::uint8_t b1 = d[1];
  if ((b0 >> 6) != kRtpVersion) return RtpErrc::kBadVersion;
  RtpHeader& h = out.header;
  h.padding = (b0 & 0x20) != 0;
  h.extension = (b0 & 0x10) != 0;
  h.csrc_count = b0 & 0x0f;
  h.marker = (b1 & 0x80) != 0;
  h.payload_type = b1 & 0x7f;
  h.sequence = load_be16(&d[2]);
  h.timestamp = load_be32(&d[4]);
  h.ssrc = load_be32(&d[8]);
  std::size_t at = kRtpFixedHeaderBytes;
  if (d.size() - at < 4u * h.csrc_count) return RtpErrc::kCsrcOverrun;
  h.csrc = {};
  for (std::size_t i = 0; i < h.csrc_count; ++i, at += 4) h.csrc[i] = load_be32(&d[at]);
  out.extension_profile = 0;
  out.extension_data = {};
  if (h.extension) {
    if (d.size() - at < 4) return RtpErrc::kExtensionOverrun;
    out.extension_profile = load_be16(&d[at]);
    const std::size_t words = load_be16(&d[at + 2]);
    at += 4;
    if (d.size() - at < 4 * words) return RtpErrc::kExtensionOverrun;
    out.extension_data = d.subspan(at, 4 * words);
    at += 4 * words;
  }
  std::size_t end = d.size();
  if (h.padding) {
    // RFC 3550 5.1: the last octet counts the padding octets, itself included.
    const std::size_t pad = d.back();
    if (pad == 0 || pad > end - at) return RtpErrc::kBadPadding;
    end -= pad;
  }
  out.payload = d.subspan(at, end - at);
  return {};
}

std::error_code pack_rtp(const RtpHeader& h, std::span<const std::uint8_t> payload,
                         std::vector<std::uint8_t>& out, std::uint8_t padding_bytes) {
  const std::size_t count = h.csrc_count & 0x0f;
  const std::size_t total = kRtpFixedHeaderBytes + 4 * count + payload.size() + padding_bytes;
  if (total > kMaxDatagramBytes) return RtpErrc::kPayloadTooLarge;
  out.reserve(out.size() + total);
  out.push_back(static_cast<std::uint8_t>((kRtpVersion << 6) | (padding_bytes ? 0x20 : 0) |
                                          count));
  out.push_back(static_cast<std::uint8_t>((h.marker ? 0x80 : 0) | (h.payload_type & 0x7f)));
  append_be16(out, h.sequence);
  append_be32(out, h.timestamp);
  append_be32(out, h.ssrc);
  for (std::size_t i = 0; i < count; ++i) append_be32(out, h.csrc[i]);
  out.insert(out.end(), payload.begin(), payload.end());
  if (padding_bytes > 0) {
    out.insert(out.end(), padding_bytes - 1u, std::uint8_t{0});
    out.push_back(padding_bytes);
  }
  return {};
}

}  // namespace fapcast
