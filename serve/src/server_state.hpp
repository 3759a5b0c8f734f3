#pragma once
// The server's state, on its network thread: the channels with their speaking session, queue
// and live clients; the sessions by id and a bounded record of finished ones; the open
// connections; the counters (behind a mutex, for stats() from any thread).
#include "beast.hpp"
#include "frame_pacer.hpp"
#include "http_connection.hpp"
#include "live_client.hpp"
#include "live_session.hpp"
#include "page_assets.hpp"
#include "request_policy.hpp"
#include "synthesis_worker.hpp"

#include "fapcast/serve/bearer_token.hpp"
#include "fapcast/serve/server.hpp"
#include "fapcast/transport/srtp_key.hpp"
#include "fapcast/utterance/speaker.hpp"

#include <nlohmann/json.hpp>

#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <unordered_map>
#include <unordered_set>

namespace fapcast {

struct Channel {
  std::shared_ptr<LiveSession> speaking;
  std::deque<std::shared_ptr<LiveSession>> queue;
  std::vector<std::shared_ptr<LiveClient>> clients;
  bool empty() const { return !speaking && queue.empty() && clients.empty(); }
};

struct Server::State : std::enable_shared_from_this<Server::State> {
  State(asio::io_context& io, ServeConfig config, ServeVoices voices, std::function<void(std::string_view)> log);
  ~State();

  void bind();  // after construction (needs weak_from_this for nothing; binds and starts accepting)
  void accept();
  void stop();
  ServeStats snapshot() const;
  void refresh_gauges();
  // A refused socket's lingering close, counted until it is closed.
  void close_lingering(tcp::socket socket);

  // HTTP
  std::optional<HttpResponse> on_head(HttpConnection& conn, const http::request_header<>& head, bool& upgrade);
  void on_request(HttpConnection& conn, HttpRequest request);
  void say(HttpConnection& conn, const HttpRequest& request);
  HttpResponse json_response(http::status status, const nlohmann::json& body, unsigned version) const;
  HttpResponse refusal(const RequestError& e, unsigned version);
  // 500 "internal" for an exception other than a RequestError, logged.
  HttpResponse internal_error(HttpConnection& conn, const std::exception& e, unsigned version);
  // Stream ids for SRTP whose SSRC no earlier stream under the key had.
  RtpStreamIds unique_srtp_ids();
  void open_live(HttpConnection& conn, const http::request_header<>& head, const std::string& channel);
  void answer_say(const std::string& id, http::status status, const nlohmann::json& body);

  // Sessions and channels
  void session_ended(const std::shared_ptr<LiveSession>& session);
  void start_next(const std::string& channel);
  void forget_channel_if_empty(const std::string& name);
  std::string new_session_id();
  nlohmann::json stats_json() const;

  template <typename F>
  void count(F f) {
    std::lock_guard lock(stats_mutex);
    f(stats);
  }
  void log_line(const std::string& line) const {
    if (log) log(line);
  }

  asio::io_context& io;
  ServeConfig config;
  ServeVoices voices;  // before the worker: jobs read them until it is joined
  std::function<void(std::string_view)> log;
  BearerToken token;
  std::optional<OriginPolicy> origins;  // once the port is known
  NetworkPolicy rtp_networks;
  std::optional<SrtpMasterKey> default_srtp_key;
  std::unordered_set<std::uint32_t> srtp_ssrcs;  // every SSRC sent under default_srtp_key
  PageAssets assets;
  std::map<std::string, std::shared_ptr<const Speaker>> speakers;  // per voice, no expression
  std::unique_ptr<SynthesisWorker> worker;
  // Sends every session's frames; before the sessions: their RTP sockets are on its io_context.
  std::unique_ptr<FramePacer> pacer;
  tcp::acceptor acceptor;
  asio::steady_timer accept_timer;  // re-arms accept after an error
  std::uint16_t bound_port = 0;

  std::map<std::string, Channel> channels;
  std::map<std::string, std::shared_ptr<LiveSession>> sessions;  // queued and active
  std::map<std::string, std::pair<std::shared_ptr<HttpConnection>, unsigned>> awaiting;  // say answers not yet sent (holds the connection)
  std::vector<std::string> languages;                            // espeak-ng's installed language codes
  std::deque<nlohmann::json> finished;                           // the last 256 ended sessions
  std::unordered_map<HttpConnection*, std::weak_ptr<HttpConnection>> connections;
  std::size_t clients_open = 0;  // accepted upgrades not yet closed
  std::size_t lingering = 0;     // refused sockets in their lingering close (linger_close)
  std::vector<std::weak_ptr<LiveClient>> all_clients;
  std::uint32_t session_numbers = 0;
  std::mt19937_64 ids{std::random_device{}()};
  bool stopping = false;
  asio::steady_timer stop_timer;  // closes the sockets of live clients that do not finish closing

  mutable std::mutex stats_mutex;
  ServeStats stats;  // frames, RTP packets and lateness: the pacer's counts
};

}  // namespace fapcast
