#include "frame_pacer.hpp"

#include "fapcast/transport/timeline.hpp"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <deque>
#include <sstream>

namespace fapcast {
namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

struct PacedStream {
  PacedStreamStart start;
  std::optional<PacedSentence> current;
  std::deque<PacedSentence> waiting;  // handed, not begun (at most one: the session makes one ahead)
  std::int64_t offset = 0;            // current sentence's first sample on the session's timeline
  std::size_t frame = 0;              // next frame of the current sentence
  std::int64_t audio_sent = 0;        // audio instants of the current sentence sent
  std::uint32_t frames_sent = 0;
  std::int64_t next_report = 0;
  Clock::time_point deadline{};
  bool finished = false;  // done or stopped: no more sends

  std::int64_t now_sample() const { return duration_to_samples(Clock::now() - start.start, start.sample_rate); }
  NtpTimestamp ntp(std::int64_t at) const {
    return to_ntp(start.wall_start + std::chrono::duration_cast<std::chrono::system_clock::duration>(
                                          samples_to_duration(at, start.sample_rate)));
  }
};

FramePacer::FramePacer(asio::io_context& network, int realtime_priority)
    : network_(network), work_(asio::make_work_guard(io_)), timer_(io_), thread_([this] {
        pthread_setname_np(pthread_self(), "fapcast-pacer");
        io_.run();
      }) {
  scheduling_.asked = realtime_priority;
  if (realtime_priority <= 0) return;
  // FIFO, not RR: the pacer is the only real-time thread and it sleeps between deadlines, so
  // there is no peer to share a time slice with.
  sched_param param{};
  param.sched_priority = realtime_priority;
  scheduling_.error = pthread_setschedparam(thread_.native_handle(), SCHED_FIFO, &param);
  if (scheduling_.error == 0) scheduling_.priority = realtime_priority;
}

FramePacer::~FramePacer() {
  stop();
  if (thread_.joinable()) thread_.join();
}

template <typename F>
void FramePacer::tell(const PacedStream& s, F f) {
  told_.emplace_back(s.start.listener, std::move(f));
}

void FramePacer::post_told() {
  if (told_.empty()) return;
  // One post per wake-up, not one per frame: each post takes the network io_context's lock,
  // which the network thread may hold while preempted. The listeners are locked on the network
  // thread, never here: the pacer holds no session.
  asio::post(network_, [told = std::exchange(told_, {})]() mutable {
    for (auto& [weak, f] : told)
      if (auto l = weak.lock()) f(*l);
  });
}

FramePacer::Handle FramePacer::open(PacedStreamStart start, PacedSentence first) {
  auto stream = std::make_shared<PacedStream>();
  stream->start = std::move(start);
  asio::post(io_, [this, stream, first = std::move(first)]() mutable {
    if (stopped_) return;
    begin_sentence(*stream, std::move(first));
    stream->deadline = stream->start.start;
    schedule(stream);
    arm();
    post_told();
  });
  return stream;
}

void FramePacer::add(const Handle& stream, PacedSentence next) {
  asio::post(io_, [this, stream, next = std::move(next)]() mutable {
    PacedStream& s = *stream;
    if (s.finished || stopped_) return;
    if (s.current) return s.waiting.push_back(std::move(next));
    // The sentence came after the one before had ended: it starts now.
    begin_sentence(s, std::move(next));
    s.deadline = s.start.start + samples_to_duration(s.offset, s.start.sample_rate);
    schedule(stream);
    arm();
    post_told();
  });
}

void FramePacer::stop(const Handle& stream) {
  asio::post(io_, [this, stream] { finish(*stream); });
}

void FramePacer::stop() {
  asio::post(io_, [this] {
    stopped_ = true;
    due_ = {};
    timer_.cancel();
    work_.reset();
  });
}

void FramePacer::begin_sentence(PacedStream& s, PacedSentence p) {
  // Sentence i + 1 starts where sentence i's audio ends, or now when it was not ready in time.
  s.offset = s.frames_sent > 0 ? std::max(s.offset, s.now_sample()) : 0;
  for (MediaUnit& u : p.units) u.sample += s.offset;
  s.current = std::move(p);
  s.frame = 0;
  s.audio_sent = 0;
  tell(s, [sentence = s.current->sentence, offset = s.offset](PacedListener& l) { l.on_sentence_begun(sentence, offset); });
}

void FramePacer::schedule(const Handle& stream) { due_.push({stream->deadline, order_++, stream}); }

void FramePacer::arm() {
  if (stopped_ || due_.empty()) return;
  const Clock::time_point next = due_.top().deadline;
  if (armed_for_ && *armed_for_ <= next) return;  // a wait for an earlier (or the same) deadline is pending
  armed_for_ = next;
  timer_.expires_at(next);
  timer_.async_wait([this](const boost::system::error_code& ec) {
    if (ec) return;  // re-armed for an earlier deadline, or stopped
    on_timer();
  });
}

void FramePacer::on_timer() {
  armed_for_.reset();
  const Clock::time_point woke = Clock::now();
  if (!due_.empty() && due_.top().deadline <= woke) wake_.add(woke - due_.top().deadline);
  // Every frame due by now, earliest first; one sent late makes the next ones later, so "now"
  // is read again before each.
  for (Clock::time_point now = woke; !due_.empty() && due_.top().deadline <= now; now = Clock::now()) {
    Due d = due_.top();
    due_.pop();
    PacedStream& s = *d.stream;
    if (s.finished || !s.current) continue;
    send_frame(s, now);
    if (!s.finished && s.current) schedule(d.stream);
  }
  arm();
  post_told();
}

void FramePacer::send_frame(PacedStream& s, Clock::time_point now) {
  const PacedSentence& p = *s.current;
  const PreparedSentence& sentence = *p.sentence;
  const SampleRate rate = s.start.sample_rate;
  const std::size_t frames = sentence.spoken.faps.frames.size();
  const std::int64_t instants = sentence.spoken.audio.instants();
  const std::int64_t here = frame_to_sample(static_cast<std::int64_t>(s.frame), s.start.rate, rate);
  const std::int64_t upto =
      s.frame + 1 < frames ? frame_to_sample(static_cast<std::int64_t>(s.frame + 1), s.start.rate, rate) : instants;
  const std::int64_t sample = s.offset + here;

  // The frame's access unit, then the audio until the next frame's sample, then a sender report
  // when one is due.
  std::size_t packets = 0;
  const std::int64_t rtcp_step = rate.hz * s.start.rtcp_interval.count() / 1000;
  const bool report = rtcp_step > 0 && sample >= s.next_report;
  std::vector<std::string> dropped;
  for (auto& r : s.start.rtp) {
    std::error_code ec;
    if (s.frame < p.units.size()) r->send_animation(p.units[s.frame], ec), ++packets;
    const auto step = static_cast<std::int64_t>(r->audio_instants_per_packet(rate, 1));
    for (std::int64_t at = s.audio_sent; !ec && at < upto; at += step, ++packets) {
      const std::int64_t count = std::min(step, upto - at);
      r->send_audio(std::span(sentence.spoken.audio.samples).subspan(static_cast<std::size_t>(at), static_cast<std::size_t>(count)),
                    1, s.offset + at, at == 0, ec);
    }
    if (!ec && report) r->send_reports(sample, s.ntp(sample), false, ec);
    if (ec) {
      // One destination that cannot be reached does not end the session for the others.
      std::ostringstream where;
      where << r->destination() << ": " << ec.message();
      dropped.push_back(where.str());
      r.reset();
    }
  }
  if (!dropped.empty()) {
    std::erase(s.start.rtp, nullptr);
    tell(s, [why = std::move(dropped)](PacedListener& l) mutable { l.on_rtp_dropped(std::move(why)); });
  }
  if (report) s.next_report = sample + rtcp_step;
  s.audio_sent = upto;
  frames_.fetch_add(1, std::memory_order_relaxed);
  rtp_packets_.fetch_add(packets, std::memory_order_relaxed);
  late_.add(now - s.deadline);
  tell(s, [f = PacedFrame{p.sentence, s.frame, here, upto, sample, s.frames_sent, now}](PacedListener& l) {
    l.on_frame_sent(f);
  });
  ++s.frames_sent;
  ++s.frame;
  if (s.frame < frames) {
    s.deadline = s.start.start + samples_to_duration(
                                     s.offset + frame_to_sample(static_cast<std::int64_t>(s.frame), s.start.rate, rate), rate);
    return;
  }
  // The sentence is spoken: the next one begins where its audio ends (or when it comes).
  const std::size_t index = sentence.index;
  tell(s, [index](PacedListener& l) { l.on_sentence_spoken(index); });
  s.offset += instants;
  s.audio_sent = 0;
  s.current.reset();
  if (index + 1 >= s.start.sentences) {
    // Told before the BYE leaves, so that whoever has seen the BYE finds the session done.
    tell(s, [](PacedListener& l) { l.on_stream_done(); });
    finish(s);
    return;
  }
  if (!s.waiting.empty()) {
    PacedSentence next = std::move(s.waiting.front());
    s.waiting.pop_front();
    begin_sentence(s, std::move(next));
    s.deadline = s.start.start + samples_to_duration(s.offset, rate);
  }
}

void FramePacer::finish(PacedStream& s) {
  if (s.finished) return;
  s.finished = true;
  if (s.frames_sent > 0) {
    // A closing report so that receivers have counts for the whole session.
    const std::int64_t last =
        s.current ? s.offset + std::min<std::int64_t>(s.audio_sent, s.current->sentence->spoken.audio.instants()) : s.offset;
    std::error_code ignored;
    for (auto& r : s.start.rtp) r->send_reports(last, s.ntp(last), true, ignored);
  }
  s.start.rtp.clear();  // its sockets close now
  s.current.reset();
  s.waiting.clear();
}

FramePacer::Counts FramePacer::counts() const {
  return {frames_.load(std::memory_order_relaxed), rtp_packets_.load(std::memory_order_relaxed),
          late_.quantile(0.5), late_.quantile(0.99), late_.max(),
          wake_.quantile(0.5), wake_.quantile(0.99), wake_.max()};
}

}  // namespace fapcast
