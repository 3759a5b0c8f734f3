#pragma once
// The sending end of one animation stream and, optionally, its audio (spec/rtp.md): the sockets
// (animation RTP at P, its RTCP at P+1, audio RTP at P+2, its RTCP at P+3, RFC 3550 11), the
// numbering and counts of both streams, the sender reports that tie them to one wallclock, and
// SRTP when a key is given. It sends what it is handed, when it is handed it: pacing is the
// caller's (RtpStreamer's blocking loop; `fapcast serve`'s timers).
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/transport/asio.hpp"
#include "fapcast/transport/media_unit.hpp"
#include "fapcast/transport/rtcp_sender_report.hpp"
#include "fapcast/transport/rtp_packet.hpp"
#include "fapcast/transport/srtp_key.hpp"
#include "fapcast/transport/srtp_session.hpp"
#include "fapcast/transport/udp_sender.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace fapcast {

// The numbering of one RTP stream: RFC 3550 wants the first sequence number and timestamp
// random; tests fix them.
struct RtpStreamIds {
  std::uint32_t ssrc = 0;
  std::uint16_t first_sequence = 0;
  std::uint32_t first_timestamp = 0;
  // Random ids from std::random_device.
  static RtpStreamIds random();
};

// "fapcast@HOSTNAME": the canonical name both streams of one sender report.
std::string default_cname();

struct RtpSenderOptions {
  std::uint8_t animation_payload_type = kDefaultFbaPayloadType;
  std::uint8_t audio_payload_type = kDefaultL16PayloadType;
  RtpStreamIds animation_ids = RtpStreamIds::random();
  RtpStreamIds audio_ids = RtpStreamIds::random();
  std::string cname = default_cname();       // SDES CNAME of both streams (ties them together)
  SenderSocketOptions socket;
  std::optional<SrtpMasterKey> srtp;         // set: every RTP and RTCP packet goes out as SRTP
};

struct StreamCounts {
  std::uint32_t packets = 0;
  std::uint32_t payload_octets = 0;  // as RTCP counts them: payload only
  std::uint32_t sender_reports = 0;
};

// Builds the RTP packet of unit `index` of a stream (exposed for tests and the benchmark).
std::error_code pack_animation_packet(const MediaUnit& unit, std::size_t index,
                                      const RtpStreamIds& ids, std::uint8_t payload_type,
                                      std::vector<std::uint8_t>& out);

// `destination` when its port P leaves room for P+3 (1..65532); else throws std::system_error
// (RtpErrc::kBadEndpoint).
udp::endpoint checked_rtp_destination(udp::endpoint destination);

class RtpSender {
 public:
  // Opens the animation sockets towards `destination` (its port is P, 1..65532) and, when
  // `with_audio`, the audio ones. Throws std::system_error (RtpErrc::kBadEndpoint for the port).
  RtpSender(asio::io_context& io, udp::endpoint destination, RtpSenderOptions options, bool with_audio);

  // The next animation packet: `unit` at its sample on the stream's timeline.
  void send_animation(const MediaUnit& unit, std::error_code& ec);
  // The next audio packet: interleaved samples of `channels` channels whose first sampling
  // instant is `first_instant` on the timeline (at most audio_instants_per_packet of them).
  // `first_packet` sets M (RFC 3551 4.1: the start of a talkspurt).
  void send_audio(std::span<const std::int16_t> interleaved, int channels, std::int64_t first_instant,
                  bool first_packet, std::error_code& ec);
  // Sender reports of both streams for media instant `sample`, shown at wallclock `ntp`; with
  // `bye`, each compound also carries a BYE for its source (RFC 3550 6.6: the stream ended).
  void send_reports(std::int64_t sample, NtpTimestamp ntp, bool bye, std::error_code& ec);

  // Instants per audio packet: 10 ms, fewer when they would not fit a datagram (with SRTP's tag).
  std::size_t audio_instants_per_packet(SampleRate sample_rate, int channels) const;

  const StreamCounts& animation_counts() const { return animation_; }
  const StreamCounts& audio_counts() const { return audio_; }
  const RtpSenderOptions& options() const { return options_; }
  udp::endpoint destination() const { return destination_; }
  bool has_audio() const { return audio_rtp_.has_value(); }

 private:
  void send_protected(UdpSender& socket, bool rtcp, std::error_code& ec);
  RtpSenderOptions options_;
  udp::endpoint destination_;
  UdpSender animation_rtp_;
  UdpSender animation_rtcp_;
  std::optional<UdpSender> audio_rtp_;
  std::optional<UdpSender> audio_rtcp_;
  std::optional<SrtpSession> srtp_;
  StreamCounts animation_;
  StreamCounts audio_;
  std::vector<std::uint8_t> packet_;
  std::vector<std::uint8_t> payload_;
};

}  // namespace fapcast
