#include "fapcast/transport/rtcp_compound.hpp"

#include "fapcast/transport/byte_order.hpp"
#include "fapcast/transport/rtp_error.hpp"

namespace fapcast {
namespace {
constexpr std::uint8_t kRtcpReceiverReportType = 201;
}

std::error_code parse_rtcp_compound(std::span<const std::uint8_t> d, RtcpCompound& out) {
  out = {};
  if (d.size() < 4) return RtpErrc::kBadRtcp;
  if (d[1] != kRtcpSenderReportType && d[1] != kRtcpReceiverReportType) return RtpErrc::kBadRtcp;
  std::size_t at = 0;
  while (at < d.size()) {
    if (d.size() - at < 4 || (d[at] >> 6) != 2) return RtpErrc::kBadRtcp;
    const std::size_t bytes = 4 * (std::size_t{load_be16(&d[at + 2])} + 1);
    if (bytes > d.size() - at) return RtpErrc::kBadRtcp;
    const auto packet = d.subspan(at, bytes);
    const std::uint8_t type = packet[1];
    const std::size_t count = packet[0] & 0x1f;
    if (type == kRtcpSenderReportType && !out.sender_report) {
      SenderReport sr;
      if (const auto ec = parse_sender_report(packet, sr)) return ec;
      out.sender_report = sr;
    } else if (type == kRtcpByeType) {
      if (4 + 4 * count > bytes) return RtpErrc::kBadRtcp;
      for (std::size_t i = 0; i < count; ++i) out.bye_sources.push_back(load_be32(&packet[4 + 4 * i]));
    }
    at += bytes;
  }
  return {};
}

void pack_bye(std::uint32_t ssrc, std::vector<std::uint8_t>& out) {
  out.push_back(0x81);  // V=2, P=0, SC=1
  out.push_back(kRtcpByeType);
  append_be16(out, 1);  // length in 32-bit words minus one
  append_be32(out, ssrc);
}

}  // namespace fapcast
