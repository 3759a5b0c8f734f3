#include "fapcast/transport/udp_url.hpp"

#include "fapcast/transport/rtp_error.hpp"

#include <charconv>
#include <stdexcept>

namespace fapcast {

std::error_code parse_udp_url(std::string_view text, UdpUrl& out) {
  constexpr std::string_view kScheme = "udp://";
  if (!text.starts_with(kScheme)) return RtpErrc::kBadEndpoint;
  std::string_view rest = text.substr(kScheme.size());
  std::string_view host;
  if (rest.starts_with('[')) {
    const auto close = rest.find(']');
    if (close == std::string_view::npos) return RtpErrc::kBadEndpoint;
    host = rest.substr(1, close - 1);
    rest = rest.substr(close + 1);
    if (!rest.starts_with(':')) return RtpErrc::kBadEndpoint;
    rest = rest.substr(1);
  } else {
    const auto colon = rest.rfind(':');
    if (colon == std::string_view::npos) return RtpErrc::kBadEndpoint;
    host = rest.substr(0, colon);
    rest = rest.substr(colon + 1);
    if (host.find(':') != std::string_view::npos) return RtpErrc::kBadEndpoint;
  }
  unsigned port = 0;
  const auto [end, err] = std::from_chars(rest.data(), rest.data() + rest.size(), port);
  if (host.empty() || rest.empty() || err != std::errc{} || end != rest.data() + rest.size() ||
      port > 65535)
    return RtpErrc::kBadEndpoint;
  out.host = std::string(host);
  out.port = static_cast<std::uint16_t>(port);
  return {};
}

udp::endpoint resolve_udp_url(asio::io_context& io, std::string_view text) {
  UdpUrl url;
  if (const auto ec = parse_udp_url(text, url))
    throw std::runtime_error(std::string(text) + ": " + ec.message());
  boost::system::error_code ec;
  const auto address = asio::ip::make_address(url.host, ec);
  if (!ec) return {address, url.port};
  udp::resolver resolver(io);
  const auto results = resolver.resolve(url.host, std::to_string(url.port), ec);
  if (ec || results.empty())
    throw std::runtime_error(std::string(text) + ": cannot resolve " + url.host + ": " +
                             ec.message());
  return results.begin()->endpoint();
}

}  // namespace fapcast
