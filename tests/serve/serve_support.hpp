#pragma once
// A fapcast::Server on loopback for the serve tests: its io_context runs on a thread of its own;
// the tests talk to it with blocking Beast clients on real sockets. The voice is the small
// SYNTHETIC one the reference talker records (support/spoken_voice.hpp); the three.js folder a
// temporary one with two small files.
#include "fapcast/core/file_io.hpp"
#include "fapcast/serve/server.hpp"
#include "fapcast/transport/asio.hpp"
#include "fapcast/voice/voice.hpp"
#include "support/run_command.hpp"
#include "support/spoken_voice.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace fapcast::test {

namespace beast = boost::beast;
namespace http = boost::beast::http;
namespace websocket = boost::beast::websocket;
using tcp = boost::asio::ip::tcp;

inline constexpr const char* kToken = "serve-test-token-0123456789abcdef";

// A folder with a token file and a small three.js folder.
inline const std::filesystem::path& serve_test_dir() {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path d = make_temp_dir("serve_test");
    write_file_atomically(d / "token", std::string(kToken) + "\n");
    std::filesystem::create_directories(d / "three" / "examples");
    write_file_atomically(d / "three" / "three.module.js", "export const REVISION = 'test';\n");
    write_file_atomically(d / "three" / "examples" / "loader.js", "// a loader\n");
    // As Debian's libjs-three has it: build/three.module.js a link to ../three.module.js.
    std::filesystem::create_directories(d / "three" / "build");
    std::filesystem::create_symlink("../three.module.js", d / "three" / "build" / "three.module.js");
    return d;
  }();
  return dir;
}

inline ServeConfig test_config() {
  ServeConfig c;
  c.host = "127.0.0.1";
  c.port = 0;
  c.token_file = serve_test_dir() / "token";
  c.three_dir = serve_test_dir() / "three";
  return c;
}

// The voice of spoken_voice.hpp, built once for all the processes of a ctest run (each test is a
// process): kept at FAPCAST_SERVE_TEST_VOICE, rebuilt when it is missing or does not open.
inline Voice serve_test_voice() {
  const std::filesystem::path cached = FAPCAST_SERVE_TEST_VOICE;
  std::error_code ec;
  if (std::filesystem::exists(cached, ec)) {
    try {
      return Voice::open(cached);
    } catch (const std::exception&) {
    }
  }
  write_file_atomically(cached, read_file(spoken_voice_file(), 64u << 20));
  return Voice::open(cached);
}

struct TestServer {
  asio::io_context io;
  std::unique_ptr<Server> server;
  std::thread thread;
  std::mutex log_mutex;
  std::vector<std::string> log;

  explicit TestServer(ServeConfig config = test_config()) {
    ServeVoices voices;
    voices.emplace("default", serve_test_voice());
    server = std::make_unique<Server>(io, std::move(config), std::move(voices), [this](std::string_view line) {
      std::lock_guard lock(log_mutex);
      log.emplace_back(line);
    });
    thread = std::thread([this] { io.run(); });
  }
  // Stops on the server's thread and waits until io.run() returned; the time it took.
  std::chrono::milliseconds stop() {
    const auto t0 = std::chrono::steady_clock::now();
    if (thread.joinable()) {
      asio::post(io, [this] { server->stop(); });
      thread.join();
    }
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - t0);
  }
  ~TestServer() {
    stop();
    server.reset();
  }
  std::uint16_t port() const { return server->port(); }
  std::vector<std::string> log_lines() {
    std::lock_guard lock(log_mutex);
    return log;
  }
};

struct Answer {
  int status = 0;
  std::string body;
  http::response<http::string_body> response;
  nlohmann::json json() const { return nlohmann::json::parse(body, nullptr, false); }
};

using Headers = std::vector<std::pair<std::string, std::string>>;

// One request on a fresh connection. `raw_body_length`: a Content-Length sent without the body.
inline Answer http_request(std::uint16_t port, http::verb verb, const std::string& target, const std::string& body = {},
                           const Headers& headers = {{"Authorization", std::string("Bearer ") + kToken}},
                           std::size_t raw_body_length = 0) {
  asio::io_context ioc;
  tcp::socket socket(ioc);
  socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  http::request<http::string_body> req{verb, target, 11};
  req.set(http::field::host, "127.0.0.1:" + std::to_string(port));
  for (const auto& [k, v] : headers) req.set(k, v);
  if (raw_body_length > 0) {
    req.set(http::field::content_length, std::to_string(raw_body_length));
    http::request_serializer<http::string_body> sr(req);
    http::write_header(socket, sr);
  } else {
    req.body() = body;
    req.prepare_payload();
    http::write(socket, req);
  }
  beast::flat_buffer buffer;
  Answer a;
  beast::error_code ec;
  http::read(socket, buffer, a.response, ec);
  a.status = static_cast<int>(a.response.result_int());
  a.body = a.response.body();
  return a;
}

inline Answer get(std::uint16_t port, const std::string& target) { return http_request(port, http::verb::get, target); }
inline Answer post(std::uint16_t port, const std::string& target, const std::string& body) {
  return http_request(port, http::verb::post, target, body);
}

// Polls GET /v1/stats until `ok(stats)`, at most 3 s.
template <typename F>
bool wait_for_stats(std::uint16_t port, F ok) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (std::chrono::steady_clock::now() < until) {
    if (ok(get(port, "/v1/stats").json())) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

// A blocking live client.
struct LiveTestClient {
  asio::io_context ioc;
  websocket::stream<tcp::socket> ws{ioc};

  // Throws beast::system_error when the handshake is refused.
  LiveTestClient(std::uint16_t port, const std::string& target, const Headers& headers = {{"Authorization", std::string("Bearer ") + kToken}}) {
    ws.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
    ws.set_option(websocket::stream_base::decorator([headers](websocket::request_type& req) {
      for (const auto& [k, v] : headers) req.set(k, v);
    }));
    ws.handshake("127.0.0.1:" + std::to_string(port), target);
  }
  struct Message {
    bool text = false;
    std::string bytes;
  };
  // The next message; empty bytes and ec set when the connection ended.
  Message read(beast::error_code& ec) {
    beast::flat_buffer b;
    ws.read(b, ec);
    return {ws.got_text(), beast::buffers_to_string(b.data())};
  }
};

}  // namespace fapcast::test
