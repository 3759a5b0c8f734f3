#include "fapcast/serve/serve_config.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/core/input_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <limits>

namespace fapcast {
namespace {
using nlohmann::json;

std::uint64_t line_of(std::string_view text, std::size_t byte) {
  byte = std::min(byte, text.size());
  return 1 + static_cast<std::uint64_t>(std::count(text.begin(), text.begin() + static_cast<long>(byte), '\n'));
}

struct Reader {
  const std::string& source;
  const std::filesystem::path& base;

  [[noreturn]] void fail(const std::string& key, const std::string& wanted) const {
    throw InputError({source, std::nullopt, std::nullopt}, "serve-config-value", key + ": expected " + wanted);
  }
  std::uint64_t integer(const json& v, const std::string& key, std::uint64_t lo, std::uint64_t hi) const {
    if (!v.is_number_integer() || (v.is_number_integer() && v.get<std::int64_t>() < 0) ||
        v.get<std::uint64_t>() < lo || v.get<std::uint64_t>() > hi)
      fail(key, "an integer " + std::to_string(lo) + ".." + std::to_string(hi));
    return v.get<std::uint64_t>();
  }
  std::string text(const json& v, const std::string& key) const {
    if (!v.is_string()) fail(key, "a string");
    return v.get<std::string>();
  }
  std::filesystem::path path(const json& v, const std::string& key) const {
    const std::filesystem::path p = text(v, key);
    return p.empty() || p.is_absolute() ? p : base / p;
  }
  bool boolean(const json& v, const std::string& key) const {
    if (!v.is_boolean()) fail(key, "true or false");
    return v.get<bool>();
  }
  std::vector<std::string> strings(const json& v, const std::string& key) const {
    if (!v.is_array()) fail(key, "an array of strings");
    std::vector<std::string> out;
    for (const json& item : v) out.push_back(text(item, key + "[]"));
    return out;
  }
  [[noreturn]] void unknown(const std::string& key) const {
    throw InputError({source, std::nullopt, std::nullopt}, "serve-config-key",
                     "unknown key '" + key + "' (spec/serve.md lists the keys)");
  }
};

void apply_limits(const json& j, const Reader& r, ServeLimits& l) {
  if (!j.is_object()) r.fail("limits", "an object");
  constexpr std::uint64_t kMiB = 1 << 20;
  for (const auto& [key, v] : j.items()) {
    const std::string name = "limits." + key;
    if (key == "max_header_bytes") l.max_header_bytes = r.integer(v, name, 1024, kMiB);
    else if (key == "max_body_bytes") l.max_body_bytes = r.integer(v, name, 256, 16 * kMiB);
    else if (key == "max_text_bytes") l.max_text_bytes = r.integer(v, name, 1, 32 * 1024);
    else if (key == "max_sessions") l.max_sessions = r.integer(v, name, 1, 100'000);
    else if (key == "max_queue") l.max_queue = r.integer(v, name, 0, 10'000);
    else if (key == "max_clients") l.max_clients = r.integer(v, name, 0, 100'000);
    else if (key == "max_connections") l.max_connections = r.integer(v, name, 1, 100'000);
    else if (key == "max_rtp_destinations") l.max_rtp_destinations = r.integer(v, name, 0, 64);
    else if (key == "max_srtp_streams") l.max_srtp_streams = r.integer(v, name, 2, 1 << 24);
    else if (key == "client_queue_frames") l.client_queue_frames = r.integer(v, name, 1, 100'000);
    else if (key == "client_send_buffer_bytes") l.client_send_buffer_bytes = r.integer(v, name, 1024, 16 * kMiB);
    else if (key == "request_timeout_ms") l.request_timeout = std::chrono::milliseconds(r.integer(v, name, 10, 3'600'000));
    else if (key == "idle_timeout_ms") l.idle_timeout = std::chrono::milliseconds(r.integer(v, name, 10, 3'600'000));
    else r.unknown(name);
  }
}

}  // namespace

std::optional<ListenAddress> parse_listen_address(std::string_view text) {
  ListenAddress out;
  std::string_view port;
  if (!text.empty() && text.front() == '[') {
    const auto close = text.find(']');
    if (close == std::string_view::npos || close + 1 >= text.size() || text[close + 1] != ':') return std::nullopt;
    out.host = std::string(text.substr(1, close - 1));
    port = text.substr(close + 2);
  } else {
    const auto colon = text.rfind(':');
    if (colon == std::string_view::npos || text.substr(0, colon).find(':') != std::string_view::npos) return std::nullopt;
    out.host = colon == 0 ? std::string("127.0.0.1") : std::string(text.substr(0, colon));
    port = text.substr(colon + 1);
  }
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (port.empty() || ec != std::errc() || end != port.data() + port.size() || value > 65535 || out.host.empty())
    return std::nullopt;
  // A host is a name or an address: no brackets (but around IPv6), blanks or control characters.
  for (const char ch : out.host)
    if (ch == '[' || ch == ']' || static_cast<unsigned char>(ch) <= ' ' || ch == '\x7f') return std::nullopt;
  out.port = static_cast<std::uint16_t>(value);
  return out;
}

void apply_serve_config(std::string_view json_text, const std::string& source, const std::filesystem::path& base_dir,
                        ServeConfig& c) {
  json j;
  try {
    j = json::parse(json_text.begin(), json_text.end());
  } catch (const json::parse_error& e) {
    throw InputError({source, line_of(json_text, e.byte == 0 ? 0 : e.byte - 1), std::nullopt}, "serve-config-json",
                     e.what());
  } catch (const json::out_of_range& e) {
    // A number beyond double's range ("1e999"): nlohmann reports it without a position.
    throw InputError({source, std::nullopt, std::nullopt}, "serve-config-json", e.what());
  }
  const Reader r{source, base_dir};
  if (!j.is_object()) r.fail("the file", "a JSON object");
  for (const auto& [key, v] : j.items()) {
    if (key == "listen") {
      const auto a = parse_listen_address(r.text(v, key));
      if (!a) r.fail(key, "HOST:PORT or [IPv6]:PORT");
      c.host = a->host;
      c.port = a->port;
    } else if (key == "token_file") {
      c.token_file = r.path(v, key);
    } else if (key == "voice") {
      c.voices["default"] = r.path(v, key);
    } else if (key == "voices") {
      if (!v.is_object() || v.empty()) r.fail(key, "an object of name: voice file");
      for (const auto& [name, file] : v.items()) c.voices[name] = r.path(file, "voices." + name);
    } else if (key == "fps") {
      c.rate = {static_cast<std::uint32_t>(r.integer(v, key, 1, 120)), 1};
    } else if (key == "allowed_origins") {
      c.allowed_origins = r.strings(v, key);
    } else if (key == "rtp_networks") {
      c.rtp_networks = r.strings(v, key);
    } else if (key == "srtp_key_file") {
      c.srtp_key_file = r.path(v, key);
    } else if (key == "require_srtp") {
      c.require_srtp = r.boolean(v, key);
    } else if (key == "multicast_ttl") {
      c.multicast_ttl = static_cast<int>(r.integer(v, key, 0, 255));
    } else if (key == "rtcp_interval_ms") {
      c.rtcp_interval = std::chrono::milliseconds(r.integer(v, key, 100, 60'000));
    } else if (key == "three_dir") {
      c.three_dir = r.path(v, key);
    } else if (key == "synthesis_threads") {
      c.synthesis_threads = r.integer(v, key, 1, 64);
    } else if (key == "sentence_bytes") {
      c.sentence_bytes = r.integer(v, key, 16, 4096);
    } else if (key == "pacer_priority") {
      c.pacer_priority = static_cast<int>(r.integer(v, key, 0, 99));
    } else if (key == "limits") {
      apply_limits(v, r, c.limits);
    } else {
      r.unknown(key);
    }
  }
}

void read_serve_config(const std::filesystem::path& path, ServeConfig& config) {
  const std::string text = read_file(path, 1 << 20);
  apply_serve_config(text, path.string(), path.parent_path(), config);
}

}  // namespace fapcast
