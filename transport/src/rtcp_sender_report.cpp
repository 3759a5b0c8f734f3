#include "fapcast/transport/rtcp_sender_report.hpp"

#include "fapcast/transport/byte_order.hpp"
#include "fapcast/transport/rtp_error.hpp"

namespace fapcast {
namespace {
constexpr std::int64_t kNtpUnixOffsetSeconds = 2'208'988'800;  // 1900-01-01 to 1970-01-01
constexpr std::size_t kSenderReportBytes = 28;                 // header 8 + sender info 20
}  // namespace

NtpTimestamp to_ntp(std::chrono::system_clock::time_point t) {
  using namespace std::chrono;
  const auto ns = duration_cast<nanoseconds>(t.time_since_epoch()).count();
  const std::int64_t secs = ns / 1'000'000'000 - (ns % 1'000'000'000 < 0 ? 1 : 0);
  const std::uint64_t rem_ns = static_cast<std::uint64_t>(ns - secs * 1'000'000'000);
  NtpTimestamp out;
  out.seconds = static_cast<std::uint32_t>(secs + kNtpUnixOffsetSeconds);  // era 0 wraps in 2036
  out.fraction = static_cast<std::uint32_t>((rem_ns << 32) / 1'000'000'000);
  return out;
}

std::chrono::system_clock::time_point from_ntp(NtpTimestamp ntp) {
  using namespace std::chrono;
  const std::int64_t secs = std::int64_t{ntp.seconds} - kNtpUnixOffsetSeconds;
  const std::uint64_t ns = ((std::uint64_t{ntp.fraction} * 1'000'000'000) + (1ull << 31)) >> 32;
  return system_clock::time_point{duration_cast<system_clock::duration>(
      seconds{secs} + nanoseconds{static_cast<std::int64_t>(ns)})};
}

void pack_sender_report(const SenderReport& sr, std::vector<std::uint8_t>& out) {
  out.push_back(0x80);  // V=2, P=0, RC=0
  out.push_back(kRtcpSenderReportType);
  append_be16(out, kSenderReportBytes / 4 - 1);  // length in 32-bit words minus one
  append_be32(out, sr.ssrc);
  append_be32(out, sr.ntp.seconds);
  append_be32(out, sr.ntp.fraction);
  append_be32(out, sr.rtp_timestamp);
  append_be32(out, sr.packet_count);
  append_be32(out, sr.octet_count);
}

void pack_sdes_cname(std::uint32_t ssrc, std::string_view cname, std::vector<std::uint8_t>& out) {
  if (cname.size() > 255) cname = cname.substr(0, 255);
  // Chunk: SSRC (4) + CNAME item (type, length, text) + at least one null, to a 4-byte boundary.
  const std::size_t chunk = (4 + 2 + cname.size() + 1 + 3) / 4 * 4;
  out.push_back(0x81);  // V=2, P=0, SC=1
  out.push_back(kRtcpSdesType);
  append_be16(out, static_cast<std::uint16_t>(chunk / 4));  // (4 + chunk) / 4 - 1
  append_be32(out, ssrc);
  out.push_back(1);  // CNAME
  out.push_back(static_cast<std::uint8_t>(cname.size()));
  out.insert(out.end(), cname.begin(), cname.end());
  out.insert(out.end(), chunk - 6 - cname.size(), std::uint8_t{0});
}

std::error_code parse_sender_report(std::span<const std::uint8_t> d, SenderReport& out) {
  if (d.size() < kSenderReportBytes) return RtpErrc::kBadRtcp;
  if ((d[0] >> 6) != 2 || d[1] != kRtcpSenderReportType) return RtpErrc::kBadRtcp;
  const std::size_t words = load_be16(&d[2]) + 1u;
  const std::size_t report_blocks = d[0] & 0x1f;
  if (4 * words > d.size() || 4 * words < kSenderReportBytes + 24 * report_blocks)
    return RtpErrc::kBadRtcp;
  out.ssrc = load_be32(&d[4]);
  out.ntp = {load_be32(&d[8]), load_be32(&d[12])};
  out.rtp_timestamp = load_be32(&d[16]);
  out.packet_count = load_be32(&d[20]);
  out.octet_count = load_be32(&d[24]);
  return {};
}

}  // namespace fapcast
