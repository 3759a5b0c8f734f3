#pragma once
// The settings of `fapcast serve`: where it listens, who may use it, what it speaks with, and the
// bound on everything a client can make it hold (spec/serve.md, "Configuration"). Built from
// defaults, then a JSON file (--config), then the command line's flags.
#include "fapcast/core/frame_rate.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

struct ServeLimits {
  std::size_t max_header_bytes = 8 * 1024;    // request line + headers (431 beyond)
  std::size_t max_body_bytes = 16 * 1024;     // request body (413 beyond)
  std::size_t max_text_bytes = 4 * 1024;      // text of one request (413 beyond)
  std::size_t max_sessions = 256;             // speaking + queued, over all channels (503)
  std::size_t max_queue = 8;                  // sessions waiting on one channel (429)
  std::size_t max_clients = 256;              // live WebSocket clients (503)
  std::size_t max_connections = 512;          // open TCP connections, HTTP and WebSocket (503)
  std::size_t max_rtp_destinations = 4;       // udp:// destinations of one request
  // Streams (SSRCs, two per SRTP destination) sent under the SRTP key since start: each SSRC is
  // drawn once per key (RFC 3711 section 9.1), so the set of them is kept; 503 beyond (a new key is needed).
  std::size_t max_srtp_streams = 1 << 20;
  std::size_t client_queue_frames = 25;       // frames waiting for one live client before it is dropped
  std::size_t client_send_buffer_bytes = 64 * 1024;  // SO_SNDBUF of a live client's socket: what the kernel holds for it
  std::chrono::milliseconds request_timeout{10'000};  // to read one request, headers and body
  std::chrono::milliseconds idle_timeout{30'000};     // a kept-alive connection with nothing to do
};

struct ServeConfig {
  std::string host = "127.0.0.1";
  std::uint16_t port = 8080;                   // 0: the system picks one (printed at start)
  std::filesystem::path token_file;            // required
  std::map<std::string, std::filesystem::path> voices;  // name -> voice file; empty path: the default voice
  FrameRate rate{25, 1};                       // frames per second of every session
  std::vector<std::string> allowed_origins;    // WebSocket/HTTP Origins accepted besides the server's own
  // Where RTP may be sent (CIDR prefixes): loopback only unless configured.
  std::vector<std::string> rtp_networks = {"127.0.0.0/8", "::1/128"};
  std::filesystem::path srtp_key_file;         // key of RTP destinations that bring none
  bool require_srtp = false;                   // refuse RTP destinations without a key
  int multicast_ttl = 1;
  std::chrono::milliseconds rtcp_interval{1000};
  std::filesystem::path three_dir = "/usr/share/javascript/three";  // Debian libjs-three
  std::size_t synthesis_threads = 1;
  std::size_t sentence_bytes = 120;            // the longest piece of text synthesised at once (sentence_offsets)
  // SCHED_FIFO priority (1..99) of the frame pacer's thread; 0: the default class. Opt-in: a
  // refusal by the system is logged and the server runs on (spec/serve.md, "Real-time priority").
  int pacer_priority = 0;
  ServeLimits limits;
};

// "HOST:PORT", "[IPv6]:PORT" or ":PORT" (host 127.0.0.1); PORT 0..65535. Nothing when malformed.
struct ListenAddress {
  std::string host;
  std::uint16_t port = 0;
};
std::optional<ListenAddress> parse_listen_address(std::string_view text);

// Applies a JSON configuration (an object; spec/serve.md lists the keys) to `config`. Relative
// paths are taken from `base_dir`. Throws InputError naming `source`: serve-config-json (with
// the line), serve-config-key (an unknown key), serve-config-value (a wrong type or range).
void apply_serve_config(std::string_view json_text, const std::string& source, const std::filesystem::path& base_dir,
                        ServeConfig& config);
// Reads the file (at most 1 MiB) and applies it; paths relative to its folder.
void read_serve_config(const std::filesystem::path& path, ServeConfig& config);

}  // namespace fapcast
