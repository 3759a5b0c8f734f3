#include "request_policy.hpp"

#include "fapcast/serve/bearer_token.hpp"
#include "fapcast/serve/say_request.hpp"

#include <charconv>
#include <stdexcept>

namespace fapcast {
namespace {

constexpr std::string_view kSessions = "/v1/sessions/";

// Calls f(name, value) for each name=value of a query; returns false when one is malformed.
template <typename F>
bool each_parameter(std::string_view query, F f) {
  while (!query.empty()) {
    const auto amp = query.find('&');
    const std::string_view item = query.substr(0, amp);
    const auto eq = item.find('=');
    if (eq == std::string_view::npos || !f(item.substr(0, eq), item.substr(eq + 1))) return false;
    if (amp == std::string_view::npos) break;
    query.remove_prefix(amp + 1);
  }
  return true;
}

bool valid_session_id(std::string_view id) {
  if (id.empty() || id.size() > 32) return false;
  for (const char c : id)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

// A relative path of plain segments (A-Z a-z 0-9 . - _), none empty, "." or "..": nothing can
// leave the folder (the files are served from memory anyway, read at start).
bool valid_asset_path(std::string_view path) {
  if (path.empty() || path.size() > 256) return false;
  std::size_t start = 0;
  while (start <= path.size()) {
    const auto slash = path.find('/', start);
    const std::string_view seg = path.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
    if (seg.empty() || seg == "." || seg == "..") return false;
    for (const char c : seg)
      if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_'))
        return false;
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  return true;
}

asio::ip::address_v6 as_v6(const asio::ip::address& a) {
  return a.is_v4() ? asio::ip::make_address_v6(asio::ip::v4_mapped, a.to_v4()) : a.to_v6();
}

}  // namespace

RouteMatch match_route(http::verb method, std::string_view target) {
  RouteMatch m;
  const auto q = target.find('?');
  const std::string_view path = target.substr(0, q);
  const std::string_view query = q == std::string_view::npos ? std::string_view() : target.substr(q + 1);
  const bool get = method == http::verb::get;  // HEAD is 405: an answer to it would need its body left out
  const auto only = [&](Route r, bool allowed) {
    m.route = r;
    m.method_allowed = allowed;
  };
  if (path == "/" || path == "/index.html") only(Route::kPage, get);
  else if (path == "/avatar.js") only(Route::kPageScript, get);
  else if (path.substr(0, 7) == "/three/" && valid_asset_path(path.substr(7))) {
    only(Route::kThree, get);
    m.asset = std::string(path.substr(7));
  } else if (path.substr(0, 4) == "/v1/") {
    if (path == "/v1/face.glb") only(Route::kFace, get);
    else if (path == "/v1/say") only(Route::kSay, method == http::verb::post);
    else if (path == "/v1/stats") only(Route::kStats, get);
    else if (path == "/v1/live") only(Route::kLive, method == http::verb::get);
    else if (path.substr(0, kSessions.size()) == kSessions) {
      std::string_view rest = path.substr(kSessions.size());
      const auto slash = rest.find('/');
      const std::string_view id = rest.substr(0, slash);
      const std::string_view tail = slash == std::string_view::npos ? std::string_view() : rest.substr(slash);
      if (valid_session_id(id) && tail.empty()) only(Route::kSession, get);
      else if (valid_session_id(id) && tail == "/stop") only(Route::kStop, method == http::verb::post);
      if (m.route != Route::kNotFound) m.session = std::string(id);
    }
  }
  if (m.route == Route::kNotFound) return m;
  const bool ok = each_parameter(query, [&](std::string_view name, std::string_view value) {
    if (get && name == "token" && !m.token) {
      // An empty ?token= presents no token: answered as a request without one (token-missing).
      if (!value.empty()) m.token = std::string(value);
      return true;
    }
    if (m.route == Route::kPage) return true;  // the page's own parameters (channel): the script reads them
    if (m.route == Route::kLive && name == "channel" && valid_name(value)) {
      m.channel = std::string(value);
      return true;
    }
    if (m.route == Route::kFace && name == "voice" && valid_name(value)) {
      m.voice = std::string(value);
      return true;
    }
    return false;
  });
  m.bad_query = !ok;
  return m;
}

std::optional<std::string> presented_token(const http::request_header<>& head, const RouteMatch& route) {
  if (const auto a = head.find(http::field::authorization); a != head.end())
    if (const auto t = bearer_credentials(std::string_view(a->value().data(), a->value().size()))) return std::string(*t);
  if (const auto p = head.find(http::field::sec_websocket_protocol); p != head.end())
    if (const auto t = subprotocol_token(std::string_view(p->value().data(), p->value().size()))) return std::string(*t);
  return route.token;
}

OriginPolicy::OriginPolicy(const std::string& host, std::uint16_t port, const std::vector<std::string>& extra)
    : allowed_(extra) {
  const std::string p = ":" + std::to_string(port);
  const bool v6 = host.find(':') != std::string::npos;
  allowed_.push_back("http://" + (v6 ? "[" + host + "]" : host) + p);
  for (const char* local : {"localhost", "127.0.0.1", "[::1]"}) allowed_.push_back(std::string("http://") + local + p);
}

bool OriginPolicy::allows(std::string_view origin) const {
  for (const std::string& a : allowed_)
    if (a == origin) return true;
  return false;
}

NetworkPolicy::NetworkPolicy(const std::vector<std::string>& prefixes) {
  for (const std::string& text : prefixes) {
    const auto slash = text.find('/');
    boost::system::error_code ec;
    const auto address = asio::ip::make_address(text.substr(0, slash), ec);
    int bits = -1;
    if (slash != std::string::npos) {
      const std::string_view b = std::string_view(text).substr(slash + 1);
      const auto [end, err] = std::from_chars(b.data(), b.data() + b.size(), bits);
      if (err != std::errc() || end != b.data() + b.size()) bits = -1;
    }
    const int width = address.is_v4() ? 32 : 128;
    if (ec || bits < 0 || bits > width) throw std::invalid_argument("rtp_networks: '" + text + "' is not ADDRESS/BITS");
    prefixes_.push_back({as_v6(address), address.is_v4() ? bits + 96 : bits});
  }
}

bool NetworkPolicy::allows(const asio::ip::address& address) const {
  const auto bytes = as_v6(address).to_bytes();
  for (const Prefix& p : prefixes_) {
    const auto net = p.network.to_bytes();
    int left = p.bits;
    bool match = true;
    for (std::size_t i = 0; i < 16 && left > 0 && match; ++i, left -= 8) {
      const int take = left >= 8 ? 8 : left;
      const auto mask = static_cast<std::uint8_t>(0xff << (8 - take));
      match = (bytes[i] & mask) == (net[i] & mask);
    }
    if (match) return true;
  }
  return false;
}

}  // namespace fapcast
