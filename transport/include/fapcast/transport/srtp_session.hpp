#pragma once
// SRTP and SRTCP (RFC 3711) through libsrtp2 (Debian libsrtp2-dev): AES-128 counter mode with a
// 10-byte HMAC-SHA1 tag on RTP and a 10-byte tag plus the 4-byte SRTCP index on RTCP, keyed by one
// master key for every SSRC of a sender (libsrtp's ssrc_any templates). A sending session
// encrypts packets in place; a receiving one authenticates first, so a packet from anyone without
// the key, a tampered one, or a copy of one already received is refused and counted, and never
// reaches the RTP parser. A layer in front of RtpStreamReceiver (UdpReceiver takes it as an
// option). spec/rtp.md section 7. Not thread-safe: one session per thread.
#include "fapcast/transport/srtp_key.hpp"

#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

namespace fapcast {

// Bytes SRTP adds to an RTP packet (the tag) and to an RTCP packet (index + tag).
inline constexpr std::size_t kSrtpRtpOverheadBytes = 10;
inline constexpr std::size_t kSrtcpOverheadBytes = 14;
// Packets a receiving session remembers for its replay check (RFC 3711 3.3.2; at least 64).
inline constexpr std::size_t kSrtpReplayWindow = 1024;

enum class SrtpDirection { kSend, kReceive };

struct SrtpStats {
  std::uint64_t protected_packets = 0;    // sent: RTP and RTCP encrypted
  std::uint64_t unprotected_packets = 0;  // received: authenticated and decrypted
  std::uint64_t auth_failed = 0;          // received: wrong tag (spoofed, tampered, foreign key)
  std::uint64_t replayed = 0;             // received: index seen before or out of the window
  std::uint64_t malformed = 0;            // received: not SRTP at all
};

class SrtpSession {
 public:
  // Throws std::runtime_error when libsrtp cannot create the session.
  SrtpSession(const SrtpMasterKey& key, SrtpDirection direction);
  ~SrtpSession();
  SrtpSession(const SrtpSession&) = delete;
  SrtpSession& operator=(const SrtpSession&) = delete;
  SrtpSession(SrtpSession&& other) noexcept;
  SrtpSession& operator=(SrtpSession&& other) noexcept;

  // Sending: encrypts one RTP (or RTCP) packet in place and appends the tag. Errors: kTooLarge
  // when the result would exceed kMaxDatagramBytes, kMalformed, kFailed.
  std::error_code protect_rtp(std::vector<std::uint8_t>& packet);
  std::error_code protect_rtcp(std::vector<std::uint8_t>& packet);
  // Receiving: authenticates and decrypts `datagram` in place; on success `length` is the RTP
  // (RTCP) packet's length, a prefix of the datagram. Errors: kAuthFailed, kReplayed, kMalformed,
  // kFailed; each is counted in stats().
  std::error_code unprotect_rtp(std::span<std::uint8_t> datagram, std::size_t& length);
  std::error_code unprotect_rtcp(std::span<std::uint8_t> datagram, std::size_t& length);

  const SrtpStats& stats() const { return stats_; }
  SrtpDirection direction() const { return direction_; }

 private:
  std::error_code protect(std::vector<std::uint8_t>& packet, bool rtcp);
  std::error_code unprotect(std::span<std::uint8_t> datagram, std::size_t& length, bool rtcp);
  void* session_ = nullptr;  // srtp_t
  SrtpDirection direction_;
  SrtpStats stats_;
};

}  // namespace fapcast
