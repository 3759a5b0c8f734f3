#pragma once
// One session: a request's text spoken sentence by sentence on a channel, streamed in real time
// to its RTP destinations and to the channel's live clients (spec/serve.md, "Sessions"). The
// network thread owns it; its sentences are synthesised on the worker threads one ahead of the
// one being sent, so that at most two are held. Frames leave at absolute deadlines on the
// session's timeline (sample 0 at the start; sentence i + 1 starts where sentence i's audio
// ends, or now if it was not ready in time), each with the audio played while it is shown.
#include "beast.hpp"
#include "fapcast/fba/fba_stream.hpp"
#include "fapcast/serve/say_request.hpp"
#include "fapcast/transport/media_unit.hpp"
#include "fapcast/transport/rtp_sender.hpp"
#include "fapcast/utterance/speaker.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fapcast {

class LiveClient;
class SynthesisWorker;

enum class SessionState { kQueued, kStarting, kSpeaking, kDone, kStopped, kFailed };
std::string_view session_state_name(SessionState state);

// A sentence ready to stream, made on a synthesis thread.
struct PreparedSentence {
  std::size_t index = 0;
  std::string text;
  SpokenSentence spoken;
  std::vector<MediaUnit> units;  // one FBA access unit per frame; samples on the sentence's audio
  std::shared_ptr<const Speaker> speaker;  // the speaker that spoke it
  std::string error;  // non-empty: synthesis refused the sentence
};

// Where a session sends RTP: its sockets are opened when it starts speaking, not while it waits
// in a queue (a full queue would otherwise hold thousands of descriptors).
struct RtpDestination {
  udp::endpoint endpoint;
  RtpSenderOptions options;
};

// What a session needs from the server, and tells it.
struct SessionContext {
  asio::io_context& io;
  SynthesisWorker& worker;
  const Voice& voice;
  std::string voice_name;
  FrameRate rate;
  std::chrono::milliseconds rtcp_interval;
  std::size_t sentence_bytes;
  // The channel's live clients, now.
  std::function<const std::vector<std::shared_ptr<LiveClient>>&()> clients;
  std::function<void(std::chrono::nanoseconds late, std::size_t rtp_packets, std::size_t messages)> on_frame;
  // Before the first frame: the answer's status, rule and detail.
  std::function<void(int status, const std::string& rule, const std::string& detail)> on_start_failed;
  std::function<void()> on_first_frame;
  std::function<void()> on_end;  // done, stopped or failed: once
  // To count: a sentence synthesised (called on the synthesis thread), RTP destinations dropped.
  std::function<void()> on_synthesised;
  std::function<void(std::size_t count)> on_rtp_dropped;
};

class LiveSession : public std::enable_shared_from_this<LiveSession> {
 public:
  // `speaker` null: one is made for the request's expression on the first synthesis job.
  LiveSession(SessionContext context, std::string id, std::uint32_t number, SayRequest request,
              std::vector<RtpDestination> rtp, std::shared_ptr<const Speaker> speaker);

  // Queued -> starting: the first sentence goes to the synthesis threads.
  void start();
  // Ends the session now (barge-in, the stop call, shutdown): RTP gets its last sender report,
  // live clients an "end" message with `reason`.
  void stop(const std::string& reason);
  // The messages that bring a client joining mid-session up to date.
  void greet(LiveClient& client) const;

  const std::string& id() const { return id_; }
  std::uint32_t number() const { return number_; }
  SessionState state() const { return state_; }
  const SayRequest& request() const { return request_; }
  bool active() const { return state_ == SessionState::kStarting || state_ == SessionState::kSpeaking; }
  // {"session", "state", "channel", "sentences", "spoken", "frames", "reason", ...}
  nlohmann::json status() const;
  // Time from start() to the first frame on the wire, and the first sentence's synthesis split.
  std::chrono::nanoseconds first_frame_latency() const { return first_frame_latency_; }

 private:
  void submit(std::size_t index);
  void on_prepared(PreparedSentence sentence);
  void begin_sentence(PreparedSentence sentence);
  void schedule();
  void tick();
  void end(SessionState state, const std::string& reason);
  void broadcast(const std::string& text) const;
  std::int64_t now_sample() const;
  std::string sentence_message(const PreparedSentence& s) const;
  std::string session_message() const;

  SessionContext ctx_;
  std::string id_;
  std::uint32_t number_;
  SayRequest request_;
  std::vector<std::size_t> sentences_;  // byte offsets of the sentences in request_.text (sentence_offsets)
  std::vector<RtpDestination> destinations_;
  std::vector<std::unique_ptr<RtpSender>> rtp_;  // opened by start(); a sender that fails to send is dropped
  std::vector<std::string> rtp_dropped_;          // "ADDRESS:PORT: why" of each dropped sender
  // Set when the session ends: a synthesis job not yet begun is skipped (a barge-in storm
  // leaves no work behind it).
  std::shared_ptr<std::atomic<bool>> cancelled_ = std::make_shared<std::atomic<bool>>(false);
  std::shared_ptr<const Speaker> speaker_;
  std::shared_ptr<FbaFrameEncoder> encoder_;  // used by one synthesis job at a time
  SessionState state_ = SessionState::kQueued;
  std::string reason_;
  asio::steady_timer timer_;

  std::optional<PreparedSentence> current_, next_;
  bool job_in_flight_ = false;
  bool waiting_for_next_ = false;
  SampleRate sample_rate_{};
  std::chrono::steady_clock::time_point started_at_{}, start_{};  // start(); sample 0
  std::chrono::system_clock::time_point wall_start_{};
  std::int64_t offset_ = 0;          // current sentence's first sample on the session's timeline
  std::size_t frame_ = 0;            // next frame of the current sentence
  std::size_t audio_sent_ = 0;       // RTP audio instants of the current sentence sent
  std::uint32_t frames_sent_ = 0;
  std::size_t sentences_spoken_ = 0;
  std::int64_t next_report_ = 0;
  std::chrono::steady_clock::time_point deadline_{};
  std::chrono::nanoseconds first_frame_latency_{0};
  std::chrono::nanoseconds first_speech_time_{0}, first_animation_time_{0};
};

}  // namespace fapcast
