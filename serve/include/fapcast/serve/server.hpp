#pragma once
// `fapcast serve`: an HTTP/1.1 + WebSocket server (Boost.Beast on Boost.Asio) that speaks text as
// it arrives. A POST /v1/say starts a session on a channel (or queues it behind the one
// speaking); its text is synthesised sentence by sentence on worker threads and streamed in real
// time, audio and animation together, to the session's RTP destinations (FBA + L16 with RTCP
// sender reports, optionally SRTP) and to every live WebSocket client of the channel. Every
// request is authenticated (bearer token, constant-time compare) and its Origin checked before
// any work; everything a client can make the server hold is bounded (ServeLimits).
// spec/serve.md is the API. One network thread: the io_context's; Server's methods are called
// on it, except stats(), which any thread may call. The frames are sent by a thread of the
// server's own (the frame pacer), so that requests and live clients do not delay them.
#include "fapcast/serve/serve_config.hpp"
#include "fapcast/transport/asio.hpp"
#include "fapcast/voice/voice.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>

namespace fapcast {

struct ServeStats {
  std::uint64_t requests = 0;            // HTTP requests read (upgrades included)
  std::uint64_t unauthorized = 0;        // 401: no or wrong token
  std::uint64_t forbidden = 0;           // 403: Origin or RTP destination not allowed
  std::uint64_t bad_requests = 0;        // 400 and 404/405
  std::uint64_t over_limits = 0;         // 413, 429, 431, 503
  std::uint64_t sessions_started = 0;    // sessions that sent their first frame
  std::uint64_t sessions_done = 0;       // ... and spoke to the end
  std::uint64_t sessions_stopped = 0;    // stopped: barge-in, the stop call, shutdown
  std::uint64_t sessions_failed = 0;     // synthesis refused the text or the RTP sockets did not open
  std::uint64_t sentences_synthesised = 0;  // synthesis jobs done (a stopped session's waiting ones are skipped)
  std::uint64_t rtp_destinations_dropped = 0;  // destinations a send failed to (the session went on)
  std::size_t sessions_speaking = 0;
  std::size_t sessions_queued = 0;
  std::size_t clients = 0;               // live WebSocket clients now
  std::uint64_t clients_accepted = 0;
  std::uint64_t clients_dropped_slow = 0;  // dropped for a full per-client queue
  std::size_t connections = 0;           // open TCP connections
  std::size_t connections_lingering = 0;  // refused ones closing (linger_close: up to 1 s or 1 MiB), not in `connections`
  std::uint64_t frames = 0;              // frame ticks over all sessions
  std::uint64_t rtp_packets = 0;         // animation + audio RTP packets sent
  std::uint64_t live_messages = 0;       // WebSocket messages queued to clients
  std::chrono::nanoseconds late_p50{0}, late_p99{0}, late_max{0};  // frame sends past their deadline
  // The frame pacer's timer waking past the earliest deadline due (the scheduler's share of the lateness).
  std::chrono::nanoseconds wake_p50{0}, wake_p99{0}, wake_max{0};
  int pacer_priority = 0;                // SCHED_FIFO priority the pacer's thread runs at; 0: the default class
};

// The voices a server speaks with, by the name a request gives ("default" when it gives none).
using ServeVoices = std::map<std::string, Voice>;

class Server {
 public:
  // Reads the token, the SRTP key and the page's three.js files, builds each voice's face for the
  // page, binds config.host:config.port and starts accepting on `io`. Throws InputError (a bad
  // token or key file), std::runtime_error (a file or the port), std::invalid_argument (no
  // voice). `log` receives one line per request (and the start and the end); empty: none.
  Server(asio::io_context& io, ServeConfig config, ServeVoices voices,
         std::function<void(std::string_view)> log = {});
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  std::uint16_t port() const;
  // http://HOST:PORT/ (IPv6 hosts in brackets).
  std::string url() const;
  // Begins a clean shutdown: stops accepting, ends every session (RTP gets its last sender
  // report, live clients an "end" message and a close frame "going away"), closes every
  // connection and stops the synthesis threads; io.run() returns once the last operation is done.
  void stop();
  // A snapshot of the counters; any thread.
  ServeStats stats() const;

 private:
  struct State;
  std::shared_ptr<State> state_;
};

}  // namespace fapcast
