// Fuzzes parse_udp_url (the URLs of stream and recv): any input either parses or is refused, and
// what parses prints back as a URL that parses to the same host and port.
#include "fapcast/transport/udp_url.hpp"

#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  UdpUrl url;
  if (parse_udp_url(std::string_view(reinterpret_cast<const char*>(data), size), url)) return 0;
  const bool bracket = url.host.find(':') != std::string::npos || url.host.starts_with('[');
  const std::string again = "udp://" + (bracket ? "[" + url.host + "]" : url.host) + ":" + std::to_string(url.port);
  UdpUrl back;
  if (parse_udp_url(again, back) || back != url) __builtin_trap();
  return 0;
}
