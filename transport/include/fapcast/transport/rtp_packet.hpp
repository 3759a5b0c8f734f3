#pragma once
// The RTP fixed header (RFC 3550 section 5.1): packing into and parsing from network bytes.
// Parsing never trusts a count in the packet: every length is checked against the bytes present.
#include <array>
#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

namespace fapcast {

inline constexpr std::uint8_t kRtpVersion = 2;
inline constexpr std::size_t kRtpFixedHeaderBytes = 12;
inline constexpr std::uint8_t kDefaultFbaPayloadType = 96;  // dynamic (RFC 3551 section 3)
inline constexpr std::uint8_t kDefaultL16PayloadType = 97;  // dynamic
// Largest datagram we send: an Ethernet MTU minus IPv6 and UDP headers.
inline constexpr std::size_t kMaxDatagramBytes = 1452;

struct RtpHeader {
  bool padding = false;             // P: the last payload byte counts padding bytes
  bool extension = false;           // X: a header extension follows the CSRC list
  bool marker = false;              // M: meaning set by the payload format (spec/rtp.md)
  std::uint8_t payload_type = kDefaultFbaPayloadType;  // 0..127
  std::uint16_t sequence = 0;       // +1 per packet, wraps at 65536
  std::uint32_t timestamp = 0;      // sampling instant of the first payload octet, media clock
  std::uint32_t ssrc = 0;           // synchronisation source
  std::uint8_t csrc_count = 0;      // 0..15
  std::array<std::uint32_t, 15> csrc{};
  bool operator==(const RtpHeader&) const = default;
};

// A parsed packet: the header plus views into the caller's buffer.
struct RtpPacketView {
  RtpHeader header;
  std::uint16_t extension_profile = 0;            // meaningful when header.extension
  std::span<const std::uint8_t> extension_data;   // the extension words, without their header
  std::span<const std::uint8_t> payload;          // without padding
};

// Parses one datagram. Errors (RtpErrc): kTruncatedHeader, kBadVersion, kCsrcOverrun,
// kExtensionOverrun, kBadPadding. On error `out` is unspecified.
std::error_code parse_rtp(std::span<const std::uint8_t> datagram, RtpPacketView& out);

// Appends header + payload (+ `padding_bytes` of padding, 0..255; header.padding is set from it)
// to `out`; header.extension is ignored (fapcast sends no extension). Errors: kPayloadTooLarge when the datagram would exceed kMaxDatagramBytes.
std::error_code pack_rtp(const RtpHeader& header, std::span<const std::uint8_t> payload,
                         std::vector<std::uint8_t>& out, std::uint8_t padding_bytes = 0);

// Bytes the header of `header` takes (12 + 4 per CSRC; extension not included).
std::size_t rtp_header_bytes(const RtpHeader& header);

}  // namespace fapcast
