// Fuzzes the receiving SRTP session (what UdpReceiver puts before the RTP and RTCP parsers): any
// datagram is refused and counted exactly once, never delivered, since no input carries the
// key's tag; and the input as the payload of an RTP packet protected under the key comes back
// unchanged, then is refused as a replay.
#include "fapcast/transport/rtp_packet.hpp"
#include "fapcast/transport/srtp_error.hpp"
#include "fapcast/transport/srtp_session.hpp"

#include <cstdint>
#include <vector>

namespace {
fapcast::SrtpMasterKey fuzz_key() {
  fapcast::SrtpMasterKey k;
  for (std::size_t i = 0; i < k.bytes.size(); ++i) k.bytes[i] = static_cast<std::uint8_t>(3 * i + 1);
  return k;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  static const SrtpMasterKey key = fuzz_key();
  SrtpSession rx(key, SrtpDirection::kReceive);
  const bool rtcp = size > 0 && (data[0] & 1);
  std::vector<std::uint8_t> datagram(data, data + size);
  std::size_t length = 0;
  const std::error_code ec = rtcp ? rx.unprotect_rtcp(datagram, length) : rx.unprotect_rtp(datagram, length);
  const SrtpStats& s = rx.stats();
  if (!ec || s.unprotected_packets != 0 || s.auth_failed + s.replayed + s.malformed != 1) __builtin_trap();

  SrtpSession tx(key, SrtpDirection::kSend);
  RtpHeader h;
  h.sequence = static_cast<std::uint16_t>(size);
  h.ssrc = 0x5eed;
  std::vector<std::uint8_t> plain;
  if (pack_rtp(h, std::vector<std::uint8_t>(data, data + size), plain)) return 0;
  std::vector<std::uint8_t> wire = plain;
  if (tx.protect_rtp(wire)) return 0;  // too large for one datagram once tagged
  std::vector<std::uint8_t> copy = wire;
  if (rx.unprotect_rtp(wire, length) || length != plain.size()) __builtin_trap();
  wire.resize(length);
  if (wire != plain) __builtin_trap();
  if (rx.unprotect_rtp(copy, length) != SrtpErrc::kReplayed) __builtin_trap();
  return 0;
}
