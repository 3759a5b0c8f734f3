#include "fapcast/transport/rtp_streamer.hpp"

#include "fapcast/transport/rtp_error.hpp"
#include "fapcast/transport/timeline.hpp"

#include <algorithm>

namespace fapcast {

RtpStreamer::RtpStreamer(asio::io_context& io, udp::endpoint destination, StreamOptions options)
    : io_(io), options_(std::move(options)), destination_(destination) {
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
  RtpSender sender(io_, destination_, options_, audio != nullptr);
  const std::int64_t clock = std::max<std::int64_t>(1, options_.clock_rate);
  const std::size_t audio_step = audio ? sender.audio_instants_per_packet(audio->sample_rate_hz, audio->channels) : 1;
  const std::int64_t audio_instants = audio ? audio->instants() : 0;
  const std::int64_t rtcp_step =
      options_.rtcp_interval.count() > 0 ? clock * options_.rtcp_interval.count() / 1000 : 0;

  // One anchor ties the media timeline to both clocks: sample s is sent at steady start + s/clock
  // and reported as wallclock wall_start + s/clock, the same instant for both streams.
  const Clock::time_point start = Clock::now();
  const auto wall_start = std::chrono::system_clock::now();
  const auto media_time = [clock](std::int64_t s) { return samples_to_duration(s, clock); };
  const auto wallclock = [&](std::int64_t s) {
    return to_ntp(wall_start + std::chrono::duration_cast<std::chrono::system_clock::duration>(media_time(s)));
  };
  asio::steady_timer timer(io_);
  std::size_t next_unit = 0;
  std::int64_t next_audio = 0;  // sampling instant of the next audio packet
  std::int64_t next_report = 0;
  const auto finish = [&] {
    report.animation = sender.animation_counts();
    report.audio = sender.audio_counts();
    return report;
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
    if (options_.pace) {
      const Clock::time_point deadline = start + media_time(at);
      const Clock::time_point now = Clock::now();
      if (now < deadline) {
        timer.expires_at(deadline);
        boost::system::error_code wait_error;
        timer.wait(wait_error);
      } else {
        report.late_total += now - deadline;
      }
    }
    if (at == report_at) {
      sender.send_reports(at, wallclock(at), ec);
      next_report += rtcp_step;
    } else if (at == unit_at) {
      sender.send_animation(animation[next_unit], ec);
      ++next_unit;
    } else {
      const std::int64_t count =
          std::min<std::int64_t>(static_cast<std::int64_t>(audio_step), audio_instants - next_audio);
      sender.send_audio(std::span(audio->samples)
                            .subspan(static_cast<std::size_t>(next_audio * audio->channels),
                                     static_cast<std::size_t>(count * audio->channels)),
                        audio->channels, next_audio, next_audio == 0, ec);
      next_audio += count;
    }
    if (ec) return finish();
  }
  // A closing report so that a receiver has counts for the whole stream.
  if (rtcp_step > 0) {
    const std::int64_t end_sample =
        std::max(audio_instants, animation.empty() ? 0 : animation.back().sample);
    sender.send_reports(end_sample, wallclock(end_sample), ec);
  }
  return finish();
}

}  // namespace fapcast
