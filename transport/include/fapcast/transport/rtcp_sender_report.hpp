#pragma once
// RTCP sender reports (RFC 3550 section 6.4.1): the NTP wallclock and the RTP timestamp of one
// instant, plus the sender's packet and octet counts. Two streams whose reports use the same
// wallclock can be played in sync (spec/rtp.md, "Lip sync").
#include <chrono>
#include <cstdint>
#include <span>
#include <string_view>
#include <system_error>
#include <vector>

namespace fapcast {

inline constexpr std::uint8_t kRtcpSenderReportType = 200;

// A 64-bit NTP timestamp: seconds since 1900-01-01 and a binary fraction of a second.
struct NtpTimestamp {
  std::uint32_t seconds = 0;
  std::uint32_t fraction = 0;  // units of 2^-32 s
  bool operator==(const NtpTimestamp&) const = default;
};

// The NTP timestamp of a system_clock instant (Unix epoch + 2,208,988,800 s).
NtpTimestamp to_ntp(std::chrono::system_clock::time_point t);
// The system_clock instant of an NTP timestamp (rounded to the clock's resolution).
std::chrono::system_clock::time_point from_ntp(NtpTimestamp ntp);

struct SenderReport {
  std::uint32_t ssrc = 0;
  NtpTimestamp ntp;               // wallclock of the instant ...
  std::uint32_t rtp_timestamp = 0;  // ... and the same instant on the stream's media clock
  std::uint32_t packet_count = 0;   // RTP packets sent since the start
  std::uint32_t octet_count = 0;    // RTP payload octets sent since the start
  bool operator==(const SenderReport&) const = default;
};

// Appends a sender report with no report blocks (28 bytes) to `out`.
void pack_sender_report(const SenderReport& sr, std::vector<std::uint8_t>& out);

inline constexpr std::uint8_t kRtcpSdesType = 202;

// Appends an SDES packet with one chunk: `ssrc` and its CNAME item (RFC 3550 6.5.1), padded
// with nulls to a 32-bit boundary. `cname` is cut to 255 bytes. A sender report followed by this
// is the smallest valid compound RTCP packet (6.1); equal CNAMEs tie a sender's streams together.
void pack_sdes_cname(std::uint32_t ssrc, std::string_view cname, std::vector<std::uint8_t>& out);

// Parses the first RTCP packet of a compound datagram if it is a sender report (report blocks
// and anything after are skipped). Errors: RtpErrc::kBadRtcp.
std::error_code parse_sender_report(std::span<const std::uint8_t> datagram, SenderReport& out);

}  // namespace fapcast
