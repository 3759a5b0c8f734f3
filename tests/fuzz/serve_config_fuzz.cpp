// Fuzzes apply_serve_config (the --config file of `fapcast serve`) and parse_listen_address:
// any file either applies or is refused with InputError (serve-config-json, -key or -value,
// naming the file); what applies keeps every bound of spec/serve.md. A listen address that parses
// prints back to one that parses to the same host and port.
#include "fapcast/core/input_error.hpp"
#include "fapcast/serve/serve_config.hpp"

#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ServeConfig c;
  try {
    apply_serve_config(text, "fuzz.json", "/base", c);
    const ServeLimits& l = c.limits;
    if (l.max_header_bytes < 1024 || l.max_body_bytes < 256 || l.max_text_bytes < 1 || l.max_text_bytes > 32 * 1024 ||
        l.max_sessions < 1 || l.max_connections < 1 || l.max_rtp_destinations > 64 || l.client_queue_frames < 1 ||
        l.request_timeout.count() < 10 || l.idle_timeout.count() < 10)
      __builtin_trap();
    if (c.rate.numerator < 1 || c.rate.numerator > 120 || c.multicast_ttl < 0 || c.multicast_ttl > 255 ||
        c.synthesis_threads < 1 || c.synthesis_threads > 64 || c.rtcp_interval.count() < 100)
      __builtin_trap();
    for (const auto& [name, file] : c.voices)
      if (!file.empty() && !file.is_absolute()) __builtin_trap();
  } catch (const InputError& e) {
    if (e.where().source != "fuzz.json" || !e.rule().starts_with("serve-config-")) __builtin_trap();
  }

  if (const auto a = parse_listen_address(text)) {
    const bool v6 = a->host.find(':') != std::string::npos;
    const std::string again = (v6 ? "[" + a->host + "]" : a->host) + ":" + std::to_string(a->port);
    const auto b = parse_listen_address(again);
    if (!b || b->host != a->host || b->port != a->port) __builtin_trap();
  }
  return 0;
}
