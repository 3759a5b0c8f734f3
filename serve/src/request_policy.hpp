#pragma once
// What the server decides from a request's head alone, before it reads a body or does any work
// (spec/serve.md, "Who may use it"): the route, the credentials presented, whether the Origin is
// one of the server's, and where RTP may go. Pure functions of their inputs: the HTTP fuzz
// target drives them with every request head Beast's parser accepts.
#include "beast.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

enum class Route {
  kPage,        // GET /                   the avatar page
  kPageScript,  // GET /avatar.js
  kThree,       // GET /three/PATH  (Debian libjs-three, read at start)
  kFace,        // GET /v1/face.glb[?voice=NAME]
  kSay,         // POST /v1/say
  kStop,        // POST /v1/sessions/ID/stop
  kSession,     // GET /v1/sessions/ID
  kStats,       // GET /v1/stats
  kLive,        // GET /v1/live[?channel=NAME] with Upgrade: websocket
  kNotFound,
};

struct RouteMatch {
  Route route = Route::kNotFound;
  bool method_allowed = true;  // false: the path exists, the method does not (405)
  std::string session;           // kStop, kSession
  std::string asset;             // kThree: PATH under the three.js folder (no "..", no empty segment)
  std::string channel = "default";  // kLive
  std::string voice = "default";    // kFace
  std::optional<std::string> token;  // ?token=T (GET requests: browsers cannot set headers on <script> or WebSocket)
  bool bad_query = false;           // a parameter that is unknown or not a valid name
};

RouteMatch match_route(http::verb method, std::string_view target);

// The token the request presents: "Authorization: Bearer T", else the subprotocol "bearer.T" a
// browser offers beside "fapcast.v1" on a WebSocket upgrade, else the route's ?token=T.
std::optional<std::string> presented_token(const http::request_header<>& head, const RouteMatch& route);

// The Origins a browser on this server's own page sends (http://HOST:PORT for the listening
// host, localhost, 127.0.0.1 and [::1]) plus the configured ones. A request without an Origin
// (not from a browser page) passes: the token is what admits it.
class OriginPolicy {
 public:
  OriginPolicy(const std::string& host, std::uint16_t port, const std::vector<std::string>& extra);
  bool allows(std::string_view origin) const;

 private:
  std::vector<std::string> allowed_;
};

// The networks RTP may be sent to (CIDR prefixes). Throws std::invalid_argument naming a bad prefix.
class NetworkPolicy {
 public:
  explicit NetworkPolicy(const std::vector<std::string>& prefixes);
  bool allows(const asio::ip::address& address) const;

 private:
  struct Prefix {
    asio::ip::address_v6 network;  // IPv4 as v4-mapped
    int bits;
  };
  std::vector<Prefix> prefixes_;
};

}  // namespace fapcast
