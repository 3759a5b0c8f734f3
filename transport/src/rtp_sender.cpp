#include "fapcast/transport/rtp_sender.hpp"

#include "fapcast/transport/fba_payload.hpp"
#include "fapcast/transport/l16.hpp"
#include "fapcast/transport/rtcp_compound.hpp"
#include "fapcast/transport/rtp_error.hpp"

#include <random>

namespace fapcast {
namespace {
udp::endpoint offset_port(udp::endpoint e, int offset) {
  return {e.address(), static_cast<std::uint16_t>(e.port() + offset)};
}
std::uint32_t rtp_timestamp(const RtpStreamIds& ids, std::int64_t sample) {
  return ids.first_timestamp + static_cast<std::uint32_t>(sample);  // modulo 2^32 by design
}
}  // namespace

udp::endpoint checked_rtp_destination(udp::endpoint destination) {
  if (destination.port() == 0 || destination.port() > 65532)
    throw std::system_error(make_error_code(RtpErrc::kBadEndpoint),
                            "destination port must be 1..65532 (P..P+3 are used)");
  return destination;
}

std::string default_cname() {
  boost::system::error_code ec;
  const std::string host = asio::ip::host_name(ec);
  return "fapcast@" + (ec || host.empty() ? std::string("localhost") : host);
}

RtpStreamIds RtpStreamIds::random() {
  std::random_device rd;
  RtpStreamIds ids;
  ids.ssrc = rd();
  ids.first_sequence = static_cast<std::uint16_t>(rd());
  ids.first_timestamp = rd();
  return ids;
}

std::error_code pack_animation_packet(const MediaUnit& unit, std::size_t index,
                                      const RtpStreamIds& ids, std::uint8_t payload_type,
                                      std::vector<std::uint8_t>& out) {
  RtpHeader h;
  h.marker = true;  // each packet ends an access unit (spec/rtp.md)
  h.payload_type = payload_type;
  h.sequence = static_cast<std::uint16_t>(ids.first_sequence + index);
  h.timestamp = rtp_timestamp(ids, unit.sample);
  h.ssrc = ids.ssrc;
  std::vector<std::uint8_t> payload;
  payload.reserve(unit.bytes.size() + 1);
  pack_fba_payload(unit.intra, unit.fapcast, unit.bytes, payload);
  return pack_rtp(h, payload, out);
}

RtpSender::RtpSender(asio::io_context& io, udp::endpoint destination, RtpSenderOptions options, bool with_audio)
    : options_(std::move(options)),
      destination_(checked_rtp_destination(destination)),
      animation_rtp_(io, destination, options_.socket),
      animation_rtcp_(io, offset_port(destination, 1), options_.socket) {
  if (with_audio) {
    audio_rtp_.emplace(io, offset_port(destination, 2), options_.socket);
    audio_rtcp_.emplace(io, offset_port(destination, 3), options_.socket);
  }
  if (options_.srtp) srtp_.emplace(*options_.srtp, SrtpDirection::kSend);
}

void RtpSender::send_protected(UdpSender& socket, bool rtcp, std::error_code& ec) {
  if (srtp_ && (ec = rtcp ? srtp_->protect_rtcp(packet_) : srtp_->protect_rtp(packet_))) return;
  socket.send(packet_, ec);
}

void RtpSender::send_animation(const MediaUnit& unit, std::error_code& ec) {
  packet_.clear();
  if ((ec = pack_animation_packet(unit, animation_.packets, options_.animation_ids,
                                  options_.animation_payload_type, packet_)))
    return;
  send_protected(animation_rtp_, false, ec);
  if (ec) return;
  ++animation_.packets;
  animation_.payload_octets += static_cast<std::uint32_t>(unit.bytes.size() + 1);
}

void RtpSender::send_audio(std::span<const std::int16_t> interleaved, int channels, std::int64_t first_instant,
                           bool first_packet, std::error_code& ec) {
  (void)channels;  // the samples are interleaved already; the count only bounds the packet
  if (!audio_rtp_) {
    ec = make_error_code(std::errc::not_connected);
    return;
  }
  RtpHeader h;
  h.marker = first_packet;  // RFC 3551 4.1: first packet of a talkspurt
  h.payload_type = options_.audio_payload_type;
  h.sequence = static_cast<std::uint16_t>(options_.audio_ids.first_sequence + audio_.packets);
  h.timestamp = rtp_timestamp(options_.audio_ids, first_instant);
  h.ssrc = options_.audio_ids.ssrc;
  payload_.clear();
  pack_l16(interleaved, payload_);
  packet_.clear();
  if ((ec = pack_rtp(h, payload_, packet_))) return;
  send_protected(*audio_rtp_, false, ec);
  if (ec) return;
  ++audio_.packets;
  audio_.payload_octets += static_cast<std::uint32_t>(payload_.size());
}

void RtpSender::send_reports(std::int64_t sample, NtpTimestamp ntp, bool bye, std::error_code& ec) {
  packet_.clear();
  pack_sender_report({options_.animation_ids.ssrc, ntp, rtp_timestamp(options_.animation_ids, sample),
                      animation_.packets, animation_.payload_octets},
                     packet_);
  pack_sdes_cname(options_.animation_ids.ssrc, options_.cname, packet_);
  if (bye) pack_bye(options_.animation_ids.ssrc, packet_);
  send_protected(animation_rtcp_, true, ec);
  if (ec) return;
  ++animation_.sender_reports;
  if (!audio_rtcp_) return;
  packet_.clear();
  pack_sender_report({options_.audio_ids.ssrc, ntp, rtp_timestamp(options_.audio_ids, sample), audio_.packets,
                      audio_.payload_octets},
                     packet_);
  pack_sdes_cname(options_.audio_ids.ssrc, options_.cname, packet_);
  if (bye) pack_bye(options_.audio_ids.ssrc, packet_);
  send_protected(*audio_rtcp_, true, ec);
  if (!ec) ++audio_.sender_reports;
}

std::size_t RtpSender::audio_instants_per_packet(SampleRate sample_rate, int channels) const {
  return l16_frames_per_packet(sample_rate, channels, srtp_ ? kSrtpRtpOverheadBytes : 0);
}

}  // namespace fapcast
