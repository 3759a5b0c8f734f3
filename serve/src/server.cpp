// The glue of `fapcast serve` (spec/serve.md): the accept loop, the checks every request passes
// before any work (connections, token, route, Origin), the routes, the channels with their
// speaking session, queue and live clients, and the clean stop.
#include "server_state.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/frontend/text_frontend.hpp"
#include "fapcast/serve/request_error.hpp"
#include "fapcast/serve/say_request.hpp"
#include "fapcast/transport/udp_url.hpp"

#include <algorithm>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace fapcast {
namespace {
using nlohmann::json;
using Clock = std::chrono::steady_clock;

constexpr std::size_t kFinishedKept = 256;

double ms(std::chrono::nanoseconds t) { return std::chrono::duration<double, std::milli>(t).count(); }

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

std::string_view header_value(const http::request_header<>& head, http::field f) {
  const auto it = head.find(f);
  return it == head.end() ? std::string_view() : std::string_view(it->value().data(), it->value().size());
}

const std::vector<std::shared_ptr<LiveClient>>& no_clients() {
  static const std::vector<std::shared_ptr<LiveClient>> none;
  return none;
}

}  // namespace

Server::State::State(asio::io_context& io_, ServeConfig config_, ServeVoices voices_,
                     std::function<void(std::string_view)> log_)
    : io(io_),
      config(std::move(config_)),
      voices(std::move(voices_)),
      log(std::move(log_)),
      token(BearerToken::from_file(config.token_file)),
      rtp_networks(config.rtp_networks),
      acceptor(io),
      accept_timer(io),
      stop_timer(io) {
  if (voices.empty()) throw std::invalid_argument("fapcast serve: no voice to speak with");
  if (!voices.contains("default")) throw std::invalid_argument("fapcast serve: no voice named 'default'");
  if (!config.srtp_key_file.empty()) default_srtp_key = read_srtp_key_file(config.srtp_key_file);
  if (config.require_srtp && !default_srtp_key)
    throw std::invalid_argument("fapcast serve: require_srtp without an SRTP key file");
  assets = load_page_assets(config.three_dir);
  for (const EspeakLanguage& l : espeak_languages()) languages.push_back(l.code);
  for (const auto& [name, voice] : voices) {
    SpeakerSettings settings;
    settings.rate = config.rate;
    settings.name = "fapcast serve";
    speakers.emplace(name, std::make_shared<const Speaker>(voice, settings, "voice '" + name + "'"));
  }
  worker = std::make_unique<SynthesisWorker>(config.synthesis_threads);
  pacer = std::make_unique<FramePacer>(io, config.pacer_priority);
}

Server::State::~State() {
  if (worker) worker->stop();
}

void Server::State::bind() {
  boost::system::error_code ec;
  const auto address = asio::ip::make_address(config.host, ec);
  if (ec) throw std::runtime_error("fapcast serve: --listen '" + config.host + "': not a numeric IP address");
  const tcp::endpoint endpoint(address, config.port);
  acceptor.open(endpoint.protocol());
  acceptor.set_option(asio::socket_base::reuse_address(true));
  acceptor.bind(endpoint, ec);
  if (ec)
    throw std::runtime_error("fapcast serve: cannot listen on " + config.host + ":" + std::to_string(config.port) + ": " +
                             ec.message());
  acceptor.listen(asio::socket_base::max_listen_connections);
  bound_port = acceptor.local_endpoint().port();
  origins.emplace(config.host, bound_port, config.allowed_origins);
  accept();
}

void Server::State::accept() {
  acceptor.async_accept([weak = weak_from_this()](boost::system::error_code ec, tcp::socket socket) {
    auto self = weak.lock();
    if (!self || self->stopping) return;
    if (ec == asio::error::operation_aborted) return;
    if (ec) {
      // Out of descriptors (EMFILE) and the like: try again shortly rather than at once, which
      // would spin the network thread while the condition lasts.
      self->log_line(std::string("fapcast serve: accept: ") + ec.message());
      self->accept_timer.expires_after(std::chrono::milliseconds(100));
      self->accept_timer.async_wait([weak](boost::system::error_code e) {
        auto s = weak.lock();
        if (s && !e && !s->stopping) s->accept();
      });
      return;
    }
    if (self->connections.size() + self->clients_open >= self->config.limits.max_connections) {
      // Over the cap: a canned answer, no connection state.
      const RequestError e(503, "too-many-connections",
                           "more than " + std::to_string(self->config.limits.max_connections) + " open connections");
      HttpResponse res = self->refusal(e, 11);
      res.keep_alive(false);
      const std::string wire = [&] {
        std::ostringstream out;
        out << res;
        return out.str();
      }();
      boost::system::error_code ignored;
      socket.non_blocking(true, ignored);
      asio::write(socket, asio::buffer(wire), ignored);  // a few hundred bytes into an empty send buffer
      self->log_line("? \"-\" 503 too-many-connections");
      self->close_lingering(std::move(socket));
      return self->accept();
    }
    {
      HttpHandler handler;
      handler.on_head = [weak](HttpConnection& c, const http::request_header<>& head, bool& upgrade) -> std::optional<HttpResponse> {
        if (auto s = weak.lock()) return s->on_head(c, head, upgrade);
        return make_response(http::status::service_unavailable, "{}", "application/json", 11);
      };
      handler.on_request = [weak](HttpConnection& c, HttpRequest request) {
        if (auto s = weak.lock()) s->on_request(c, std::move(request));
      };
      handler.log = [weak](const std::string& line) {
        if (auto s = weak.lock()) s->log_line(line);
      };
      handler.on_refused = [weak](int status) {
        if (auto s = weak.lock()) s->count([status](ServeStats& st) { ++(status == 400 ? st.bad_requests : st.over_limits); });
      };
      handler.close_lingering = [weak](tcp::socket s) {
        if (auto st = weak.lock()) st->close_lingering(std::move(s));
        else linger_close(std::move(s));
      };
      handler.on_closed = [weak](HttpConnection& c) {
        if (auto s = weak.lock()) {
          s->connections.erase(&c);
          s->refresh_gauges();
        }
      };
      const ServeLimits& l = self->config.limits;
      auto conn = std::make_shared<HttpConnection>(std::move(socket), l.max_header_bytes, l.max_body_bytes,
                                                   l.request_timeout, l.idle_timeout, std::move(handler));
      self->connections.emplace(conn.get(), conn);
      self->refresh_gauges();
      conn->start();
    }
    self->accept();
  });
}

void Server::State::close_lingering(tcp::socket socket) {
  ++lingering;
  refresh_gauges();
  linger_close(std::move(socket), [weak = weak_from_this()] {
    if (auto s = weak.lock()) {
      --s->lingering;
      s->refresh_gauges();
    }
  });
}

void Server::State::refresh_gauges() {
  std::size_t speaking = 0, queued = 0, clients = 0;
  for (const auto& [name, ch] : channels) {
    speaking += ch.speaking ? 1 : 0;
    queued += ch.queue.size();
    clients += ch.clients.size();
  }
  std::lock_guard lock(stats_mutex);
  stats.sessions_speaking = speaking;
  stats.sessions_queued = queued;
  stats.clients = clients;
  stats.connections = connections.size() + clients_open;
  stats.connections_lingering = lingering;
}

ServeStats Server::State::snapshot() const {
  std::lock_guard lock(stats_mutex);
  ServeStats s = stats;
  const FramePacer::Counts paced = pacer->counts();
  s.frames = paced.frames;
  s.rtp_packets = paced.rtp_packets;
  s.late_p50 = paced.late_p50;
  s.late_p99 = paced.late_p99;
  s.late_max = paced.late_max;
  s.wake_p50 = paced.wake_p50;
  s.wake_p99 = paced.wake_p99;
  s.wake_max = paced.wake_max;
  s.pacer_priority = pacer->scheduling().priority;
  return s;
}

json Server::State::stats_json() const {
  const ServeStats s = snapshot();
  return {{"requests", s.requests},
          {"unauthorized", s.unauthorized},
          {"forbidden", s.forbidden},
          {"bad_requests", s.bad_requests},
          {"over_limits", s.over_limits},
          {"sessions_started", s.sessions_started},
          {"sessions_done", s.sessions_done},
          {"sessions_stopped", s.sessions_stopped},
          {"sessions_failed", s.sessions_failed},
          {"sentences_synthesised", s.sentences_synthesised},
          {"rtp_destinations_dropped", s.rtp_destinations_dropped},
          {"sessions_speaking", s.sessions_speaking},
          {"sessions_queued", s.sessions_queued},
          {"clients", s.clients},
          {"clients_accepted", s.clients_accepted},
          {"clients_dropped_slow", s.clients_dropped_slow},
          {"connections", s.connections},
          {"frames", s.frames},
          {"rtp_packets", s.rtp_packets},
          {"live_messages", s.live_messages},
          {"late_p50_ms", ms(s.late_p50)},
          {"late_p99_ms", ms(s.late_p99)},
          {"late_max_ms", ms(s.late_max)},
          {"wake_p50_ms", ms(s.wake_p50)},
          {"wake_p99_ms", ms(s.wake_p99)},
          {"wake_max_ms", ms(s.wake_max)},
          {"connections_lingering", s.connections_lingering},
          {"pacer_priority", s.pacer_priority}};
}

HttpResponse Server::State::json_response(http::status status, const json& body, unsigned version) const {
  return make_response(status, dump(body), "application/json", version);
}

HttpResponse Server::State::refusal(const RequestError& e, unsigned version) {
  count([&](ServeStats& s) {
    const int st = e.status();
    if (st == 401) ++s.unauthorized;
    else if (st == 403) ++s.forbidden;
    else if (st == 413 || st == 429 || st == 431 || st == 503) ++s.over_limits;
    else ++s.bad_requests;
  });
  HttpResponse res = make_response(static_cast<http::status>(e.status()), request_error_body(e), "application/json", version);
  if (e.status() == 401) res.set(http::field::www_authenticate, "Bearer realm=\"fapcast\"");
  return res;
}

std::optional<HttpResponse> Server::State::on_head(HttpConnection& conn, const http::request_header<>& head,
                                                   bool& upgrade) {
  count([](ServeStats& s) { ++s.requests; });
  const unsigned v = head.version();
  try {
    if (stopping) throw RequestError(503, "shutting-down", "the server is stopping");
    const std::string_view target(head.target().data(), head.target().size());
    const RouteMatch route = match_route(head.method(), target);
    // The token first: nothing about the server (not even which paths exist) is told to a
    // client without it.
    const auto presented = presented_token(head, route);
    if (!presented) throw RequestError(401, "token-missing", "send 'Authorization: Bearer TOKEN' (spec/serve.md)");
    if (!token.matches(*presented)) throw RequestError(401, "token-wrong", "the bearer token is not this server's");
    if (route.route == Route::kNotFound) throw RequestError(404, "not-found", "no such resource (spec/serve.md lists the API)");
    if (!route.method_allowed)
      throw RequestError(405, "method-not-allowed", std::string(head.method_string()) + " is not allowed here");
    if (route.bad_query) throw RequestError(400, "query-invalid", "an unknown parameter or a bad name in the query");
    const std::string_view origin = header_value(head, http::field::origin);
    const bool checks_origin = route.route == Route::kLive || head.method() == http::verb::post;
    if (checks_origin && !origin.empty() && !origins->allows(origin))
      throw RequestError(403, "origin-forbidden", "Origin '" + std::string(origin.substr(0, 200)) + "' is not allowed");
    if (route.route == Route::kLive) {
      if (!websocket::is_upgrade(head))
        throw RequestError(400, "websocket-required", "/v1/live is a WebSocket endpoint (Upgrade: websocket)");
      if (clients_open >= config.limits.max_clients)
        throw RequestError(503, "too-many-clients", "at most " + std::to_string(config.limits.max_clients) + " live clients");
      upgrade = true;
      open_live(conn, head, route.channel);
      return std::nullopt;
    }
    return std::nullopt;
  } catch (const RequestError& e) {
    return refusal(e, v);
  } catch (const std::exception& e) {
    return internal_error(conn, e, v);
  }
}

void Server::State::on_request(HttpConnection& conn, HttpRequest request) {
  const unsigned v = request.version();
  const std::string_view target(request.target().data(), request.target().size());
  const RouteMatch route = match_route(request.method(), target);
  try {
    switch (route.route) {
      case Route::kPage: return conn.respond(make_response(http::status::ok, assets.page_html, "text/html; charset=utf-8", v));
      case Route::kPageScript:
        return conn.respond(make_response(http::status::ok, assets.page_script, "text/javascript; charset=utf-8", v));
      case Route::kThree: {
        const auto it = assets.three.find(route.asset);
        if (it == assets.three.end()) throw RequestError(404, "not-found", "no such three.js file");
        const bool js = route.asset.ends_with(".js");
        return conn.respond(make_response(http::status::ok, it->second,
                                          js ? "text/javascript; charset=utf-8" : "application/octet-stream", v));
      }
      case Route::kFace: {
        if (!voices.contains(route.voice)) throw RequestError(404, "voice-unknown", "no voice '" + route.voice + "'");
        auto it = assets.face_glb.find(route.voice);
        if (it == assets.face_glb.end()) it = assets.face_glb.emplace(route.voice, face_glb(voices.at(route.voice), route.voice)).first;
        if (!it->second)
          throw RequestError(404, "face-unavailable", "voice '" + route.voice + "' has no face on the ICT topology");
        return conn.respond(make_response(http::status::ok, *it->second, "model/gltf-binary", v));
      }
      case Route::kStats: return conn.respond(json_response(http::status::ok, stats_json(), v));
      case Route::kSession:
      case Route::kStop: {
        if (const auto it = sessions.find(route.session); it != sessions.end()) {
          const std::shared_ptr<LiveSession> s = it->second;
          if (route.route == Route::kStop) s->stop("stopped");
          return conn.respond(json_response(http::status::ok, s->status(), v), route.route == Route::kStop ? "stopped" : "");
        }
        for (const json& f : finished)
          if (f.value("session", std::string()) == route.session) return conn.respond(json_response(http::status::ok, f, v));
        throw RequestError(404, "session-unknown", "no session '" + route.session + "' (or it ended long ago)");
      }
      case Route::kSay: return say(conn, request);
      case Route::kLive:
      case Route::kNotFound: break;
    }
    throw RequestError(404, "not-found", "no such resource");
  } catch (const RequestError& e) {
    conn.respond(refusal(e, v), e.rule());
  } catch (const std::exception& e) {
    conn.respond(internal_error(conn, e, v), "internal");
  }
}

HttpResponse Server::State::internal_error(HttpConnection& conn, const std::exception& e, unsigned version) {
  // A bug or an exhausted resource while handling one request: that request gets a 500, the
  // server goes on (an exception escaping io.run() would end it).
  log_line(conn.peer() + " \"" + conn.request_line() + "\" internal error: " + e.what());
  return refusal(RequestError(500, "internal", "the server could not handle this request (its log says why)"), version);
}

RtpStreamIds Server::State::unique_srtp_ids() {
  // RFC 3711 section 9.1: under one master key every SSRC must be distinct (the keystream
  // depends on the SSRC and the packet index only).
  for (;;) {
    RtpStreamIds ids = RtpStreamIds::random();
    if (srtp_ssrcs.insert(ids.ssrc).second) return ids;
  }
}

std::string Server::State::new_session_id() {
  for (;;) {
    std::ostringstream id;
    id << std::hex << std::setw(16) << std::setfill('0') << ids();
    if (!sessions.contains(id.str())) return id.str();
  }
}

void Server::State::say(HttpConnection& conn, const HttpRequest& request) {
  const unsigned v = request.version();
  SayRequest r = parse_say_request(request.body(), {config.limits.max_text_bytes, config.limits.max_rtp_destinations});
  if (!voices.contains(r.voice)) throw RequestError(400, "voice-unknown", "no voice '" + r.voice + "' on this server");
  if (r.lang != "en-us" && std::find(languages.begin(), languages.end(), r.lang) == languages.end())
    throw RequestError(400, "lang-unsupported", "'" + r.lang + "' is not an installed espeak-ng language");
  std::vector<udp::endpoint> destinations;
  for (const UdpUrl& u : r.rtp) {
    boost::system::error_code ec;
    const auto address = asio::ip::make_address(u.host, ec);
    if (ec) throw RequestError(400, "rtp-url", "'" + u.host.substr(0, 100) + "': RTP needs a numeric IP address");
    if (!rtp_networks.allows(address))
      throw RequestError(403, "rtp-forbidden", address.to_string() + " is not in the networks RTP may be sent to");
    destinations.emplace_back(address, u.port);
  }
  const bool srtp = r.srtp.value_or(default_srtp_key.has_value());
  if (srtp && !default_srtp_key) throw RequestError(400, "srtp-unavailable", "'srtp': the server has no SRTP key");
  if (!srtp && config.require_srtp && !destinations.empty())
    throw RequestError(403, "srtp-required", "this server sends RTP as SRTP only");
  if (sessions.size() >= config.limits.max_sessions)
    throw RequestError(503, "too-many-sessions", "at most " + std::to_string(config.limits.max_sessions) + " sessions");
  const auto found = channels.find(r.channel);
  Channel* const existing = found == channels.end() ? nullptr : &found->second;
  if (!r.interrupt && existing && existing->speaking && existing->queue.size() >= config.limits.max_queue)
    throw RequestError(429, "queue-full", "channel '" + r.channel + "' has " + std::to_string(existing->queue.size()) +
                                              " sessions waiting (limit " + std::to_string(config.limits.max_queue) + ")");
  if (srtp && srtp_ssrcs.size() + 2 * destinations.size() > config.limits.max_srtp_streams)
    throw RequestError(503, "srtp-streams-exhausted",
                       "the SRTP key has served " + std::to_string(srtp_ssrcs.size()) + " of the " +
                           std::to_string(config.limits.max_srtp_streams) +
                           " streams it may (RFC 3711: each SSRC once per key); start the server with a new key");
  std::vector<RtpDestination> planned;
  for (const udp::endpoint& d : destinations) {
    RtpDestination p{d, {}};
    if (srtp) {
      p.options.srtp = default_srtp_key;
      p.options.animation_ids = unique_srtp_ids();
      p.options.audio_ids = unique_srtp_ids();
    }
    if (d.address().is_multicast()) p.options.socket.ttl = config.multicast_ttl;
    planned.push_back(std::move(p));
  }
  if (r.interrupt && existing) {
    Channel& channel = *existing;
    // Barge-in: what the channel is saying stops, and what waits is dropped.
    auto queue = std::move(channel.queue);
    channel.queue.clear();
    const std::shared_ptr<LiveSession> speaking = channel.speaking;  // the stops may forget the channel
    for (auto& q : queue) q->stop("interrupted");
    if (speaking) speaking->stop("interrupted");
  }
  Channel& ready = channels[r.channel];  // the stops may have forgotten the channel
  const std::string id = new_session_id();
  const std::string channel_name = r.channel;
  const bool plain = r.lang == "en-us" && !r.ssml && !r.expression;
  std::shared_ptr<const Speaker> speaker = plain ? speakers.at(r.voice) : nullptr;
  std::weak_ptr<State> weak = weak_from_this();
  SessionContext ctx{io, *pacer, *worker, voices.at(r.voice), r.voice, config.rate, config.rtcp_interval, config.sentence_bytes, {}, {}, {}, {}, {}, {}, {}};
  ctx.clients = [weak, channel_name]() -> const std::vector<std::shared_ptr<LiveClient>>& {
    auto s = weak.lock();
    if (!s) return no_clients();
    const auto it = s->channels.find(channel_name);
    return it == s->channels.end() ? no_clients() : it->second.clients;
  };
  ctx.on_live_messages = [weak](std::size_t messages) {
    if (auto s = weak.lock()) s->count([messages](ServeStats& st) { st.live_messages += messages; });
  };
  ctx.on_synthesised = [weak]() {  // on a synthesis thread: count() takes the stats mutex
    if (auto s = weak.lock()) s->count([](ServeStats& st) { ++st.sentences_synthesised; });
  };
  ctx.on_rtp_dropped = [weak](std::size_t n) {
    if (auto s = weak.lock()) s->count([n](ServeStats& st) { st.rtp_destinations_dropped += n; });
  };
  ctx.on_start_failed = [weak, id](int status, const std::string& rule, const std::string& why) {
    if (auto s = weak.lock()) s->answer_say(id, static_cast<http::status>(status), {{"error", rule}, {"detail", why}});
  };
  ctx.on_first_frame = [weak, id]() {
    auto s = weak.lock();
    if (!s) return;
    s->count([](ServeStats& st) { ++st.sessions_started; });
    if (const auto it = s->sessions.find(id); it != s->sessions.end())
      s->answer_say(id, http::status::accepted, it->second->status());
  };
  ctx.on_end = [weak, id]() {
    auto s = weak.lock();
    if (!s) return;
    const auto it = s->sessions.find(id);
    if (it == s->sessions.end()) return;
    const std::shared_ptr<LiveSession> keep = it->second;  // session_ended erases the map's
    s->session_ended(keep);
  };
  auto session = std::make_shared<LiveSession>(std::move(ctx), id, ++session_numbers, std::move(r), std::move(planned),
                                               std::move(speaker));
  sessions.emplace(id, session);
  awaiting.emplace(id, std::make_pair(conn.shared_from_this(), v));
  if (ready.speaking) {
    ready.queue.push_back(session);
    // A queued session is answered now: its speaking may be far off.
    answer_say(id, http::status::accepted, session->status());
  } else {
    ready.speaking = session;
    session->start();
  }
  refresh_gauges();
}

void Server::State::answer_say(const std::string& id, http::status status, const json& body) {
  const auto it = awaiting.find(id);
  if (it == awaiting.end()) return;
  const std::shared_ptr<HttpConnection> conn = it->second.first;
  const unsigned v = it->second.second;
  awaiting.erase(it);
  HttpResponse res = json_response(status, body, v);
  if (status == http::status::accepted) res.set(http::field::location, "/v1/sessions/" + id);
  conn->respond(std::move(res), "session " + id + " " + body.value("state", std::string("failed")));
}

void Server::State::session_ended(const std::shared_ptr<LiveSession>& session) {
  const std::string id = session->id();
  const std::string channel_name = session->request().channel;
  json status = session->status();
  count([&](ServeStats& s) {
    switch (session->state()) {
      case SessionState::kDone: ++s.sessions_done; break;
      case SessionState::kStopped: ++s.sessions_stopped; break;
      default: ++s.sessions_failed; break;
    }
  });
  // A session that ended before it spoke (stopped while its first sentence was made) answers
  // its request with how it ended.
  if (session->state() != SessionState::kFailed) answer_say(id, http::status::accepted, status);
  else answer_say(id, http::status::unprocessable_entity, status);
  finished.push_back(std::move(status));
  while (finished.size() > kFinishedKept) finished.pop_front();
  sessions.erase(id);
  if (const auto it = channels.find(channel_name); it != channels.end()) {
    Channel& ch = it->second;
    std::erase(ch.queue, session);
    if (ch.speaking == session) {
      ch.speaking.reset();
      start_next(channel_name);
    }
  }
  forget_channel_if_empty(channel_name);
  refresh_gauges();
}

void Server::State::start_next(const std::string& name) {
  const auto it = channels.find(name);
  if (it == channels.end() || stopping) return;
  Channel& ch = it->second;
  if (ch.speaking || ch.queue.empty()) return;
  const std::shared_ptr<LiveSession> next = ch.queue.front();
  ch.queue.pop_front();
  ch.speaking = next;
  next->start();
}

void Server::State::forget_channel_if_empty(const std::string& name) {
  const auto it = channels.find(name);
  if (it != channels.end() && it->second.empty()) channels.erase(it);
}

void Server::State::open_live(HttpConnection& conn, const http::request_header<>& head, const std::string& channel) {
  const std::string peer = conn.peer();
  const std::string line = conn.request_line();
  http::request<http::empty_body> request{http::request_header<>(head)};
  beast::tcp_stream stream = conn.release_stream();
  ++clients_open;
  std::weak_ptr<State> weak = weak_from_this();
  LiveClient::Hooks hooks;
  hooks.on_open = [weak](LiveClient& c) {
    auto s = weak.lock();
    if (!s) return;
    auto client = c.shared_from_this();
    if (s->stopping) return c.close(websocket::close_code::going_away, "server shutting down");
    Channel& ch = s->channels[c.channel()];
    ch.clients.push_back(client);
    s->all_clients.push_back(client);
    s->count([](ServeStats& st) { ++st.clients_accepted; });
    if (ch.speaking) ch.speaking->greet(c);
    s->refresh_gauges();
  };
  hooks.on_close = [weak, peer](LiveClient& c, const std::string& why) {
    auto s = weak.lock();
    if (!s) return;
    // Not while a session may be iterating over the channel's clients: after it.
    asio::post(s->io, [weak, client = c.shared_from_this(), why, peer]() {
      auto st = weak.lock();
      if (!st) return;
      --st->clients_open;
      if (why.starts_with("slow-client")) st->count([](ServeStats& x) { ++x.clients_dropped_slow; });
      if (const auto it = st->channels.find(client->channel()); it != st->channels.end()) {
        std::erase(it->second.clients, client);
        st->forget_channel_if_empty(client->channel());
      }
      std::erase_if(st->all_clients, [&](const std::weak_ptr<LiveClient>& w) {
        auto p = w.lock();
        return !p || p == client;
      });
      st->log_line(peer + " live client of channel '" + client->channel() + "' closed: " + why);
      if (st->stopping && st->all_clients.empty()) st->stop_timer.cancel();
      st->refresh_gauges();
    });
  };
  auto client = std::make_shared<LiveClient>(std::move(stream), channel, peer, config.limits.client_queue_frames,
                                             config.limits.client_send_buffer_bytes, std::move(hooks));
  log_line(peer + " \"" + line + "\" 101 live client of channel '" + channel + "'");
  client->accept(std::move(request));
}

void Server::State::stop() {
  if (stopping) return;
  stopping = true;
  boost::system::error_code ignored;
  acceptor.close(ignored);
  accept_timer.cancel();
  // Sessions end first, so that live clients get their "end" before the close frame.
  std::vector<std::shared_ptr<LiveSession>> all;
  for (const auto& [id, s] : sessions) all.push_back(s);
  for (auto& s : all) s->stop("shutdown");
  for (const auto& w : all_clients)
    if (auto c = w.lock()) c->close(websocket::close_code::going_away, "server shutting down");
  std::vector<std::shared_ptr<HttpConnection>> open;
  for (const auto& [p, w] : connections)
    if (auto c = w.lock()) open.push_back(c);
  for (auto& c : open) c->close();
  worker->stop();
  pacer->stop();  // after the sessions' closing reports, handed to it above
  stop_timer.expires_after(std::chrono::seconds(1));
  stop_timer.async_wait([weak = weak_from_this()](boost::system::error_code ec) {
    auto s = weak.lock();
    if (!s || ec) return;
    for (const auto& w : s->all_clients)
      if (auto c = w.lock()) c->abort();
  });
  if (all_clients.empty()) stop_timer.cancel();  // nothing to wait for: io.run() need not wait 1 s
  log_line("fapcast serve: stopping");
}

// ---------------------------------------------------------------------------------------------

Server::Server(asio::io_context& io, ServeConfig config, ServeVoices voices, std::function<void(std::string_view)> log)
    : state_(std::make_shared<State>(io, std::move(config), std::move(voices), std::move(log))) {
  state_->bind();
  state_->log_line("fapcast serve: listening on " + url());
  const FramePacer::Scheduling pacing = state_->pacer->scheduling();
  if (pacing.priority > 0) {
    state_->log_line("fapcast serve: frame pacer at real-time priority " + std::to_string(pacing.priority) + " (SCHED_FIFO)");
  } else if (pacing.asked > 0) {
    // Said once, at start, and the server runs on: frames are still paced, only a busy machine
    // may delay them (stats' pacer_priority is 0).
    state_->log_line("fapcast serve: frame pacer: real-time priority " + std::to_string(pacing.asked) +
                     " (SCHED_FIFO) refused: " + std::strerror(pacing.error) +
                     " (it needs CAP_SYS_NICE or RLIMIT_RTPRIO >= " + std::to_string(pacing.asked) +
                     "); running at the default priority");
  }
}

Server::~Server() {
  if (state_) state_->stop();
}

std::uint16_t Server::port() const { return state_->bound_port; }

std::string Server::url() const {
  const std::string& h = state_->config.host;
  const bool v6 = h.find(':') != std::string::npos;
  return "http://" + (v6 ? "[" + h + "]" : h) + ":" + std::to_string(state_->bound_port) + "/";
}

void Server::stop() { state_->stop(); }

ServeStats Server::stats() const { return state_->snapshot(); }

}  // namespace fapcast
