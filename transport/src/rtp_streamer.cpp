#include "fapcast/transport/rtp_streamer.hpp"

#include "wait_until.hpp"

#include "fapcast/transport/fba_payload.hpp"
#include "fapcast/transport/rtcp_compound.hpp"
#include "fapcast/transport/l16.hpp"
#include "fapcast/transport/rtp_error.hpp"
#include "fapcast/transport/timeline.hpp"

#include <algorithm>
#include <random>

namespace fapcast {
namespace {
constexpr int kClosingReports = 3;
constexpr std::chrono::milliseconds kClosingGap{10};

udp::endpoint offset_port(udp::endpoint e, int offset) {
  return {e.address(), static_cast<std::uint16_t>(e.port() + offset)};
}
std::uint32_t rtp_timestamp(const RtpStreamIds& ids, std::int64_t sample) {
  return ids.first_timestamp + static_cast<std::uint32_t>(sample);  // modulo 2^32 by design
}
}  // namespace

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

RtpStreamer::RtpStreamer(asio::io_context& io, udp::endpoint destination, StreamOptions options)
    : io_(io),
      options_(options),
      animation_rtp_(io, destination, options.socket),
      animation_rtcp_(io, offset_port(destination, 1), options.socket),
      destination_(destination) {
  if (destination.port() == 0 || destination.port() > 65532)
    throw std::system_error(make_error_code(RtpErrc::kBadEndpoint),
                            "destination port must be 1..65532 (P..P+3 are used)");
}

StreamReport RtpStreamer::run(const std::vector<MediaUnit>& animation, const Audio* audio) {
  std::error_code ec;
  StreamReport report = run(animation, audio, ec);
  if (ec) throw std::system_error(ec, "stream to " + destination_.address().to_string());
  return report;
}

StreamReport RtpStreamer::run(const std::vector<MediaUnit>& animation, const Audio* audio,
                              std::error_code& ec) {
  using Clock = std::chrono::steady_clock;
  ec.clear();
  StreamReport report;
  const std::int64_t clock = std::max<std::int64_t>(1, options_.clock_rate.hz);
  if (audio && !audio_rtp_) {
    audio_rtp_.emplace(io_, offset_port(destination_, 2), options_.socket);
    audio_rtcp_.emplace(io_, offset_port(destination_, 3), options_.socket);
  }
  const std::size_t audio_step =
      audio ? l16_frames_per_packet(audio->sample_rate, audio->channels) : 1;
  const std::int64_t audio_instants = audio ? audio->instants() : 0;
  const std::int64_t rtcp_step =
      options_.rtcp_interval.count() > 0 ? clock * options_.rtcp_interval.count() / 1000 : 0;

  // One anchor ties the media timeline to both clocks: sample s is sent at steady start + s/clock
  // and reported as wallclock wall_start + s/clock, the same instant for both streams.
  const Clock::time_point start = Clock::now();
  const auto wall_start = std::chrono::system_clock::now();
  const auto media_time = [clock](std::int64_t s) { return samples_to_duration(s, SampleRate{clock}); };
  asio::steady_timer timer(io_);
  std::vector<std::uint8_t> packet;
  std::size_t next_unit = 0;
  std::int64_t next_audio = 0;  // sampling instant of the next audio packet
  std::size_t audio_index = 0;
  std::int64_t next_report = 0;

  const auto send_reports = [&](std::int64_t s, bool bye) {
    const NtpTimestamp ntp = to_ntp(wall_start + std::chrono::duration_cast<
                                                     std::chrono::system_clock::duration>(media_time(s)));
    packet.clear();
    pack_sender_report({options_.animation_ids.ssrc, ntp, rtp_timestamp(options_.animation_ids, s),
                        report.animation.packets, report.animation.payload_octets},
                       packet);
    pack_sdes_cname(options_.animation_ids.ssrc, options_.cname, packet);
    if (bye) pack_bye(options_.animation_ids.ssrc, packet);
    animation_rtcp_.send(packet, ec);
    if (!ec) ++report.animation.sender_reports;
    if (audio && !ec) {
      packet.clear();
      pack_sender_report({options_.audio_ids.ssrc, ntp, rtp_timestamp(options_.audio_ids, s),
                          report.audio.packets, report.audio.payload_octets},
                         packet);
      pack_sdes_cname(options_.audio_ids.ssrc, options_.cname, packet);
      if (bye) pack_bye(options_.audio_ids.ssrc, packet);
      audio_rtcp_->send(packet, ec);
      if (!ec) ++report.audio.sender_reports;
    }
  };

  for (;;) {
    // The next event on the media timeline: an animation unit, an audio packet or a report.
    constexpr std::int64_t kNever = INT64_MAX;
    const std::int64_t unit_at = next_unit < animation.size() ? animation[next_unit].sample : kNever;
    const std::int64_t audio_at = next_audio < audio_instants ? next_audio : kNever;
    const bool media_left = unit_at != kNever || audio_at != kNever;
    if (!media_left) break;
    const std::int64_t report_at = rtcp_step > 0 ? next_report : kNever;
    const std::int64_t at = std::min({unit_at, audio_at, report_at});
    if (options_.pace) report.late_total += detail::wait_until(timer, start + media_time(at));
    if (at == report_at) {
      send_reports(at, false);
      next_report += rtcp_step;
    } else if (at == unit_at) {
      packet.clear();
      const MediaUnit& unit = animation[next_unit];
      if ((ec = pack_animation_packet(unit, next_unit, options_.animation_ids,
                                      options_.animation_payload_type, packet)))
        return report;
      animation_rtp_.send(packet, ec);
      ++report.animation.packets;
      report.animation.payload_octets += static_cast<std::uint32_t>(unit.bytes.size() + 1);
      ++next_unit;
    } else {
      const std::int64_t count =
          std::min<std::int64_t>(static_cast<std::int64_t>(audio_step), audio_instants - next_audio);
      RtpHeader h;
      h.marker = audio_index == 0;  // RFC 3551 4.1: first packet of a talkspurt
      h.payload_type = options_.audio_payload_type;
      h.sequence = static_cast<std::uint16_t>(options_.audio_ids.first_sequence + audio_index);
      h.timestamp = rtp_timestamp(options_.audio_ids, next_audio);
      h.ssrc = options_.audio_ids.ssrc;
      std::vector<std::uint8_t> payload;
      pack_l16(std::span(audio->samples)
                   .subspan(static_cast<std::size_t>(next_audio * audio->channels),
                            static_cast<std::size_t>(count * audio->channels)),
               payload);
      packet.clear();
      if ((ec = pack_rtp(h, payload, packet))) return report;
      audio_rtp_->send(packet, ec);
      ++report.audio.packets;
      report.audio.payload_octets += static_cast<std::uint32_t>(payload.size());
      next_audio += count;
      ++audio_index;
    }
    if (ec) return report;
  }
  // A closing report with BYE (RFC 3550 6.6) so that a receiver has counts for the whole stream
  // and knows it ended; sent kClosingReports times, kClosingGap apart when paced, since one lost
  // datagram would otherwise cost the receiver the stream's last frames and its end.
  if (rtcp_step > 0) {
    const std::int64_t end_sample =
        std::max(audio_instants, animation.empty() ? 0 : animation.back().sample);
    for (int i = 0; i < kClosingReports && !ec; ++i) {
      if (i > 0 && options_.pace) {
        timer.expires_after(kClosingGap);
        boost::system::error_code wait_error;
        timer.wait(wait_error);
      }
      send_reports(end_sample, true);
    }
  }
  return report;
}

}  // namespace fapcast
