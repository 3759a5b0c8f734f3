// Fuzzes what `fapcast serve` does with a request's bytes before any work, without a socket: the
// bytes go through Beast's request parser with the connection's bounds (header and body limits,
// as HttpConnection sets them), then the head through the route, the presented token and the
// Origin policy, a POST /v1/say body through parse_say_request, and its RTP destinations through
// the network policy. Every request is either refused by the parser (a Beast error: 400, 413 or
// 431) or routed; what is routed keeps the route's rules (a session id of hex digits, valid
// channel and voice names, a three.js asset path that cannot leave its folder), and the body's
// answer is a RequestError or a request. (The server's on_head, which strings these together, needs a live connection; the
// named bad requests of tests/data/serve/bad drive it over a real socket.)
#include "request_policy.hpp"

#include "fapcast/serve/bearer_token.hpp"
#include "fapcast/serve/request_error.hpp"
#include "fapcast/serve/say_request.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace {

constexpr std::size_t kHeaderLimit = 1024;
constexpr std::size_t kBodyLimit = 2048;

bool hex_id(std::string_view id) {
  if (id.empty() || id.size() > 32) return false;
  for (const char c : id)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

// A relative path whose segments are all names: no "", "." or "..".
bool inside_folder(std::string_view path) {
  if (path.empty()) return false;
  for (std::size_t start = 0;;) {
    const auto slash = path.find('/', start);
    const auto seg = path.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
    if (seg.empty() || seg == "." || seg == "..") return false;
    if (slash == std::string_view::npos) return true;
    start = slash + 1;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  static const OriginPolicy origins("127.0.0.1", 8080, {"https://app.example"});
  static const NetworkPolicy networks({"127.0.0.0/8", "::1/128", "239.0.0.0/8", "ff05::/16"});

  http::request_parser<http::string_body> parser;
  parser.header_limit(static_cast<std::uint32_t>(kHeaderLimit));
  parser.body_limit(kBodyLimit);
  parser.eager(true);
  beast::error_code ec;
  std::size_t at = 0;
  while (at < size && !parser.is_done()) {
    const std::size_t used = parser.put(asio::buffer(data + at, size - at), ec);
    if (ec == http::error::need_more) {
      ec = {};
      break;  // the connection would wait for more bytes (then time out)
    }
    if (ec) break;
    if (used == 0) break;
    at += used;
  }
  if (!ec && !parser.is_done() && parser.is_header_done() && at == size) parser.put_eof(ec);
  if (ec) {
    // What the connection answers: 431 header-too-large, 413 body-too-large, else 400 http-malformed.
    return 0;
  }
  if (!parser.is_header_done()) return 0;

  const auto& head = parser.get();
  const std::string_view target(head.target().data(), head.target().size());
  if (target.size() > kHeaderLimit) __builtin_trap();
  const RouteMatch m = match_route(head.method(), target);
  if (m.route == Route::kNotFound) return 0;
  if (m.route == Route::kThree && !inside_folder(m.asset)) __builtin_trap();
  if ((m.route == Route::kStop || m.route == Route::kSession) != !m.session.empty()) __builtin_trap();
  if (!m.session.empty() && !hex_id(m.session)) __builtin_trap();
  if (!valid_name(m.channel) || !valid_name(m.voice)) __builtin_trap();

  if (const auto token = presented_token(head, m)) {
    // Whatever it holds is only compared with the token (BearerToken::matches), never parsed further.
    if (token->empty()) __builtin_trap();
  }
  if (const auto origin = head.find(http::field::origin); origin != head.end())
    (void)origins.allows(std::string_view(origin->value().data(), origin->value().size()));

  if (m.route != Route::kSay || !m.method_allowed || !parser.is_done()) return 0;
  const std::string& body = parser.get().body();
  if (body.size() > kBodyLimit) __builtin_trap();
  try {
    const SayRequest r = parse_say_request(body, SayLimits{});
    for (const UdpUrl& url : r.rtp) {
      boost::system::error_code bad;
      const auto address = asio::ip::make_address(url.host, bad);
      if (!bad) (void)networks.allows(address);
    }
  } catch (const RequestError& e) {
    if (e.status() != 400 && e.status() != 413) __builtin_trap();
  }
  return 0;
}
