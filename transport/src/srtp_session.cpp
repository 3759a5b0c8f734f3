#include "fapcast/transport/srtp_session.hpp"

#include "fapcast/transport/rtp_packet.hpp"
#include "fapcast/transport/srtp_error.hpp"

#include <srtp2/srtp.h>

#include <cstring>
#include <utility>
#include <mutex>
#include <stdexcept>
#include <string>

namespace fapcast {
namespace {

void init_libsrtp() {
  static std::once_flag once;
  static srtp_err_status_t status = srtp_err_status_ok;
  std::call_once(once, [] { status = srtp_init(); });
  if (status != srtp_err_status_ok)
    throw std::runtime_error("libsrtp2: srtp_init failed with status " + std::to_string(status));
}

srtp_t ctx(void* p) { return static_cast<srtp_t>(p); }

// The smallest packets libsrtp may be handed: an RTP fixed header, an RTCP header + SSRC.
constexpr std::size_t kMinRtpBytes = kRtpFixedHeaderBytes;
constexpr std::size_t kMinRtcpBytes = 8;

}  // namespace

SrtpSession::SrtpSession(const SrtpMasterKey& key, SrtpDirection direction) : direction_(direction) {
  init_libsrtp();
  srtp_policy_t policy;
  std::memset(&policy, 0, sizeof policy);
  srtp_crypto_policy_set_aes_cm_128_hmac_sha1_80(&policy.rtp);
  srtp_crypto_policy_set_aes_cm_128_hmac_sha1_80(&policy.rtcp);
  policy.ssrc.type = direction == SrtpDirection::kSend ? ssrc_any_outbound : ssrc_any_inbound;
  policy.key = const_cast<unsigned char*>(key.bytes.data());  // libsrtp copies it
  policy.window_size = kSrtpReplayWindow;
  policy.allow_repeat_tx = 0;
  policy.next = nullptr;
  srtp_t session = nullptr;
  if (const srtp_err_status_t s = srtp_create(&session, &policy); s != srtp_err_status_ok)
    throw std::runtime_error("libsrtp2: srtp_create failed with status " + std::to_string(s));
  session_ = session;
}

SrtpSession::~SrtpSession() {
  if (session_) srtp_dealloc(ctx(session_));
}

SrtpSession::SrtpSession(SrtpSession&& other) noexcept
    : session_(std::exchange(other.session_, nullptr)), direction_(other.direction_), stats_(other.stats_) {}

SrtpSession& SrtpSession::operator=(SrtpSession&& other) noexcept {
  if (this != &other) {
    if (session_) srtp_dealloc(ctx(session_));
    session_ = std::exchange(other.session_, nullptr);
    direction_ = other.direction_;
    stats_ = other.stats_;
  }
  return *this;
}

std::error_code SrtpSession::protect_rtp(std::vector<std::uint8_t>& packet) { return protect(packet, false); }
std::error_code SrtpSession::protect_rtcp(std::vector<std::uint8_t>& packet) { return protect(packet, true); }
std::error_code SrtpSession::unprotect_rtp(std::span<std::uint8_t> datagram, std::size_t& length) {
  return unprotect(datagram, length, false);
}
std::error_code SrtpSession::unprotect_rtcp(std::span<std::uint8_t> datagram, std::size_t& length) {
  return unprotect(datagram, length, true);
}

std::error_code SrtpSession::protect(std::vector<std::uint8_t>& packet, bool rtcp) {
  if (direction_ != SrtpDirection::kSend) return SrtpErrc::kFailed;
  if (packet.size() < (rtcp ? kMinRtcpBytes : kMinRtpBytes)) return SrtpErrc::kMalformed;
  const std::size_t overhead = rtcp ? kSrtcpOverheadBytes : kSrtpRtpOverheadBytes;
  if (packet.size() + overhead > kMaxDatagramBytes) return SrtpErrc::kTooLarge;
  int length = static_cast<int>(packet.size());
  packet.resize(packet.size() + SRTP_MAX_TRAILER_LEN + 4);  // libsrtp writes the trailer in place
  const srtp_err_status_t s =
      rtcp ? srtp_protect_rtcp(ctx(session_), packet.data(), &length) : srtp_protect(ctx(session_), packet.data(), &length);
  if (s != srtp_err_status_ok) {
    packet.resize(packet.size() - SRTP_MAX_TRAILER_LEN - 4);
    return s == srtp_err_status_bad_param || s == srtp_err_status_parse_err ? SrtpErrc::kMalformed : SrtpErrc::kFailed;
  }
  packet.resize(static_cast<std::size_t>(length));
  ++stats_.protected_packets;
  return {};
}

std::error_code SrtpSession::unprotect(std::span<std::uint8_t> datagram, std::size_t& length, bool rtcp) {
  const auto refuse = [&](SrtpErrc e) -> std::error_code {
    (e == SrtpErrc::kAuthFailed ? stats_.auth_failed : e == SrtpErrc::kReplayed ? stats_.replayed : stats_.malformed)++;
    return e;
  };
  if (direction_ != SrtpDirection::kReceive) return SrtpErrc::kFailed;
  const std::size_t overhead = rtcp ? kSrtcpOverheadBytes : kSrtpRtpOverheadBytes;
  if (datagram.size() < (rtcp ? kMinRtcpBytes : kMinRtpBytes) + overhead || datagram.size() > 65536)
    return refuse(SrtpErrc::kMalformed);
  // libsrtp reads 32-bit words of the header: hand it an aligned copy (a vector's storage).
  std::vector<std::uint8_t> aligned(datagram.begin(), datagram.end());
  int n = static_cast<int>(aligned.size());
  const srtp_err_status_t s =
      rtcp ? srtp_unprotect_rtcp(ctx(session_), aligned.data(), &n) : srtp_unprotect(ctx(session_), aligned.data(), &n);
  switch (s) {
    case srtp_err_status_ok: break;
    case srtp_err_status_auth_fail: return refuse(SrtpErrc::kAuthFailed);
    case srtp_err_status_replay_fail:
    case srtp_err_status_replay_old: return refuse(SrtpErrc::kReplayed);
    default: return refuse(SrtpErrc::kMalformed);
  }
  if (n < 0 || static_cast<std::size_t>(n) > datagram.size()) return refuse(SrtpErrc::kMalformed);
  std::memcpy(datagram.data(), aligned.data(), static_cast<std::size_t>(n));
  length = static_cast<std::size_t>(n);
  ++stats_.unprotected_packets;
  return {};
}

}  // namespace fapcast
