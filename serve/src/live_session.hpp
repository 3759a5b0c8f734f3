#pragma once
// One session: a request's text spoken sentence by sentence on a channel, streamed in real time
// to its RTP destinations and to the channel's live clients (spec/serve.md, "Sessions"). The
// network thread owns it; its sentences are synthesised on the worker threads one ahead of the
// one being sent, so that at most two are held. Its frames are sent by the frame pacer
// (frame_pacer.hpp) at absolute deadlines on the session's timeline (sample 0 at the start;
// sentence i + 1 starts where sentence i's audio ends, or now if it was not ready in time), each
// with the audio played while it is shown; the pacer tells it each frame sent, and it sends the
// frame's message to the channel's live clients.
#include "beast.hpp"
#include "frame_pacer.hpp"
#include "prepared_sentence.hpp"

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

// Where a session sends RTP: its sockets are opened when it starts speaking, not while it waits
// in a queue (a full queue would otherwise hold thousands of descriptors).
struct RtpDestination {
  udp::endpoint endpoint;
  RtpSenderOptions options;
};

// What a session needs from the server, and tells it.
struct SessionContext {
  asio::io_context& io;  // the network thread's
  FramePacer& pacer;
  SynthesisWorker& worker;
  const Voice& voice;
  std::string voice_name;
  FrameRate rate;
  std::chrono::milliseconds rtcp_interval;
  std::size_t sentence_bytes;
  // The channel's live clients, now.
  std::function<const std::vector<std::shared_ptr<LiveClient>>&()> clients;
  std::function<void(std::size_t messages)> on_live_messages;  // queued to live clients
  // Before the first frame: the answer's status, rule and detail.
  std::function<void(int status, const std::string& rule, const std::string& detail)> on_start_failed;
  std::function<void()> on_first_frame;
  std::function<void()> on_end;  // done, stopped or failed: once
  // To count: a sentence synthesised (called on the synthesis thread), RTP destinations dropped.
  std::function<void()> on_synthesised;
  std::function<void(std::size_t count)> on_rtp_dropped;
};

class LiveSession : public PacedListener, public std::enable_shared_from_this<LiveSession> {
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
  // PacedListener: what the pacer did.
  void on_sentence_begun(std::shared_ptr<const PreparedSentence> sentence, std::int64_t offset) override;
  void on_frame_sent(const PacedFrame& frame) override;
  void on_sentence_spoken(std::size_t index) override;
  void on_rtp_dropped(std::vector<std::string> why) override;
  void on_stream_done() override;
  void end(SessionState state, const std::string& reason);
  void broadcast(const std::string& text) const;
  std::string sentence_message(const PreparedSentence& s, std::int64_t offset) const;
  std::string session_message() const;

  SessionContext ctx_;
  std::string id_;
  std::uint32_t number_;
  SayRequest request_;
  std::vector<std::size_t> sentences_;  // byte offsets of the sentences in request_.text (sentence_offsets)
  std::vector<RtpDestination> destinations_;
  std::vector<std::unique_ptr<RtpSender>> rtp_;  // opened by start(), handed to the pacer with the first sentence
  std::vector<std::string> rtp_dropped_;          // "ADDRESS:PORT: why" of each dropped sender
  // Set when the session ends: a synthesis job not yet begun is skipped (a barge-in storm
  // leaves no work behind it).
  std::shared_ptr<std::atomic<bool>> cancelled_ = std::make_shared<std::atomic<bool>>(false);
  std::shared_ptr<const Speaker> speaker_;
  std::shared_ptr<FbaFrameEncoder> encoder_;  // used by one synthesis job at a time
  SessionState state_ = SessionState::kQueued;
  std::string reason_;

  std::shared_ptr<PacedStream> stream_;              // at the pacer, while speaking
  std::shared_ptr<const PreparedSentence> playing_;  // the sentence being sent (for a client that joins)
  std::int64_t playing_offset_ = 0;                  // its first sample on the session's timeline
  std::size_t handed_ = 0;                           // sentences handed to the pacer
  bool job_in_flight_ = false;
  SampleRate sample_rate_{};
  std::chrono::steady_clock::time_point started_at_{};  // start()
  std::uint32_t frames_sent_ = 0;
  std::size_t sentences_spoken_ = 0;
  std::chrono::nanoseconds first_frame_latency_{0};
  std::chrono::nanoseconds first_speech_time_{0}, first_animation_time_{0};
};

}  // namespace fapcast
