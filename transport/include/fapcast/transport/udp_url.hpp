#pragma once
// `udp://HOST:PORT` addresses for the command line: HOST is an IPv4 address, [IPv6] or a name.
#include "fapcast/transport/asio.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>

namespace fapcast {

struct UdpUrl {
  std::string host;        // without brackets
  std::uint16_t port = 0;  // 0 lets the system choose (receivers only)
  bool operator==(const UdpUrl&) const = default;
};

// Splits "udp://HOST:PORT". Errors: RtpErrc::kBadEndpoint.
std::error_code parse_udp_url(std::string_view text, UdpUrl& out);

// Resolves a URL to one endpoint (numeric addresses without a lookup). Throws
// std::runtime_error naming the URL when it is malformed or the name does not resolve.
udp::endpoint resolve_udp_url(asio::io_context& io, std::string_view text);

}  // namespace fapcast
