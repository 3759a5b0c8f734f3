#pragma once
// The clock of every speaking session (spec/serve.md, "Frame pacing"): one thread with its own
// io_context and one timer, armed for the earliest deadline of all sessions, that sends each
// due frame's RTP (the FBA access unit, the audio shown with it, a sender report when one is
// due) in deadline order. Nothing else runs on it: requests, the synthesis hand-over and the
// live (WebSocket) clients stay on the network thread, so that a frame waits for other frames
// only. The two threads share nothing but what they post to each other and the counters
// (atomics: the pacer takes no lock a reader could hold): the network thread hands a session's
// RTP senders and sentences over and tells it to stop; the pacer posts back, to the network
// io_context, what the frames of one wake-up sent, in one post.
#include "beast.hpp"
#include "lateness_histogram.hpp"
#include "prepared_sentence.hpp"

#include "fapcast/core/frame_rate.hpp"
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/transport/rtp_sender.hpp"

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <queue>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace fapcast {

// One frame the pacer sent, told to the network thread (its live clients' message is built there).
struct PacedFrame {
  std::shared_ptr<const PreparedSentence> sentence;
  std::size_t frame = 0;                    // in the sentence
  std::int64_t first = 0, end = 0;          // its audio: [first, end) of the sentence's samples
  std::int64_t sample = 0;                  // `first` on the session's timeline
  std::uint32_t sequence = 0;               // frames of the session sent before it
  std::chrono::steady_clock::time_point sent;  // when its sends began
};

// What a paced session tells its owner; called on the network thread (posted there).
class PacedListener {
 public:
  virtual ~PacedListener() = default;
  // Sentence `sentence` starts at `offset` on the session's timeline (before its frames).
  virtual void on_sentence_begun(std::shared_ptr<const PreparedSentence> sentence, std::int64_t offset) = 0;
  virtual void on_frame_sent(const PacedFrame& frame) = 0;
  virtual void on_sentence_spoken(std::size_t index) = 0;
  // Destinations a send failed to ("ADDRESS:PORT: why"), dropped.
  virtual void on_rtp_dropped(std::vector<std::string> why) = 0;
  // The last sentence's last frame is sent and the closing reports (SR + BYE) with it.
  virtual void on_stream_done() = 0;
};

// A sentence handed to the pacer: the shared part (read by the network thread too) and its
// access units, the pacer's own (their samples move onto the session's timeline).
struct PacedSentence {
  std::shared_ptr<const PreparedSentence> sentence;
  std::vector<MediaUnit> units;
};

// The opening of a paced session.
struct PacedStreamStart {
  std::weak_ptr<PacedListener> listener;
  std::vector<std::unique_ptr<RtpSender>> rtp;  // opened on the pacer's io_context
  SampleRate sample_rate;
  FrameRate rate;
  std::chrono::milliseconds rtcp_interval{0};
  std::size_t sentences = 0;  // of the session: after the last one's last frame, it is done
  std::chrono::steady_clock::time_point start;  // sample 0
  std::chrono::system_clock::time_point wall_start;
};

struct PacedStream;  // a paced session; touched on the pacer thread only

class FramePacer {
 public:
  using Handle = std::shared_ptr<PacedStream>;

  // `network`: where the listeners' calls are posted. `realtime_priority` 1..99: the thread runs
  // in SCHED_FIFO at that priority, so that a busy machine does not delay its wake-ups (spec/serve.md,
  // "Real-time priority"); 0: the default class (SCHED_OTHER). A refusal (no CAP_SYS_NICE, a
  // too-low RLIMIT_RTPRIO) leaves the default class: scheduling() says which.
  explicit FramePacer(asio::io_context& network, int realtime_priority = 0);
  ~FramePacer();  // stop(), then joins the thread
  FramePacer(const FramePacer&) = delete;
  FramePacer& operator=(const FramePacer&) = delete;

  // The pacer's io_context: for the sockets of RtpSenders handed to it.
  asio::io_context& io() { return io_; }
  // From the network thread: a session that starts speaking `first` now; more sentences; the
  // end (the closing reports are sent unless it is done already).
  Handle open(PacedStreamStart start, PacedSentence first);
  void add(const Handle& stream, PacedSentence next);
  void stop(const Handle& stream);
  // What was handed before it is done first; then the thread ends.
  void stop();

  // Frames sent, RTP packets, how late each frame's sends began against its deadline, and how
  // late the timer woke against the earliest deadline due (the scheduler's part of it).
  struct Counts {
    std::uint64_t frames = 0, rtp_packets = 0;
    std::chrono::nanoseconds late_p50{0}, late_p99{0}, late_max{0};
    std::chrono::nanoseconds wake_p50{0}, wake_p99{0}, wake_max{0};
  };
  Counts counts() const;

  // The scheduling the thread got: `priority` > 0 when it runs in SCHED_FIFO; `error` the errno
  // of the refusal when one was asked for and not given (0 otherwise).
  struct Scheduling {
    int asked = 0, priority = 0, error = 0;
  };
  Scheduling scheduling() const { return scheduling_; }

 private:
  struct Due {
    std::chrono::steady_clock::time_point deadline;
    std::uint64_t order;  // FIFO among equal deadlines
    Handle stream;
    bool operator>(const Due& o) const { return deadline != o.deadline ? deadline > o.deadline : order > o.order; }
  };
  void schedule(const Handle& stream);
  void arm();
  void on_timer();
  void send_frame(PacedStream& s, std::chrono::steady_clock::time_point now);
  void begin_sentence(PacedStream& s, PacedSentence p);
  void finish(PacedStream& s);  // closing reports; no more frames
  template <typename F>
  void tell(const PacedStream& s, F f);
  void post_told();  // what tell() gathered, to the network thread, in one post

  asio::io_context& network_;
  asio::io_context io_;
  asio::executor_work_guard<asio::io_context::executor_type> work_;
  asio::steady_timer timer_;
  std::optional<std::chrono::steady_clock::time_point> armed_for_;
  std::priority_queue<Due, std::vector<Due>, std::greater<>> due_;
  std::uint64_t order_ = 0;
  bool stopped_ = false;

  std::vector<std::pair<std::weak_ptr<PacedListener>, std::function<void(PacedListener&)>>> told_;
  std::atomic<std::uint64_t> frames_{0}, rtp_packets_{0};
  LatenessHistogram late_, wake_;
  Scheduling scheduling_;

  std::thread thread_;  // last: starts when the rest is ready
};

}  // namespace fapcast
