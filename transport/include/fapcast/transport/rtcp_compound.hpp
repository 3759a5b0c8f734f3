#pragma once
// Compound RTCP packets as a receiver reads them (RFC 3550 6.1): every packet of the datagram is
// walked by its length; the sender report (6.4.1) and the BYE (6.6) are kept, other types (SDES,
// RR, APP) are skipped. A BYE is what lets a receiver give up a validated source (spec/rtp.md).
#include "fapcast/transport/rtcp_sender_report.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <system_error>
#include <vector>

namespace fapcast {

inline constexpr std::uint8_t kRtcpByeType = 203;

struct RtcpCompound {
  std::optional<SenderReport> sender_report;  // the first SR of the datagram
  std::vector<std::uint32_t> bye_sources;     // every SSRC a BYE lists (at most 31 per BYE)
};

// Parses a whole compound datagram. Errors (RtpErrc::kBadRtcp): version not 2, a packet whose
// length runs past the datagram, a datagram that does not start with SR or RR (6.1), a BYE
// whose source count does not fit its length.
std::error_code parse_rtcp_compound(std::span<const std::uint8_t> datagram, RtcpCompound& out);

// Appends a BYE packet for one source, without a reason (8 bytes).
void pack_bye(std::uint32_t ssrc, std::vector<std::uint8_t>& out);

}  // namespace fapcast
