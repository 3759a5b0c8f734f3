#include "fapcast/transport/rtp_streamer.hpp"

#include "wait_until.hpp"

#include "fapcast/transport/timeline.hpp"

#include <algorithm>

namespace fapcast {
namespace {
constexpr int kClosingReports = 3;
constexpr std::chrono::milliseconds kClosingGap{10};
}  // namespace

RtpStreamer::RtpStreamer(asio::io_context& io, udp::endpoint destination, StreamOptions options)
    : io_(io), options_(std::move(options)), destination_(checked_rtp_destination(destination)) {}

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
  const std::int64_t clock = std::max<std::int64_t>(1, options_.clock_rate.hz);
  const std::size_t audio_step = audio ? sender.audio_instants_per_packet(audio->sample_rate, audio->channels) : 1;
  const std::int64_t audio_instants = audio ? audio->instants() : 0;
  const std::int64_t rtcp_step =
      options_.rtcp_interval.count() > 0 ? clock * options_.rtcp_interval.count() / 1000 : 0;

  // One anchor ties the media timeline to both clocks: sample s is sent at steady start + s/clock
  // and reported as wallclock wall_start + s/clock, the same instant for both streams.
  const Clock::time_point start = Clock::now();
  const auto wall_start = std::chrono::system_clock::now();
  const auto media_time = [clock](std::int64_t s) { return samples_to_duration(s, SampleRate{clock}); };
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
    if (options_.pace) report.late_total += detail::wait_until(timer, start + media_time(at));
    if (at == report_at) {
      sender.send_reports(at, wallclock(at), false, ec);
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
      sender.send_reports(end_sample, wallclock(end_sample), true, ec);
    }
  }
  return finish();
}

}  // namespace fapcast
