#pragma once
// Loopback clients of `fapcast serve` for its tests and benchmarks: raw HTTP requests over a real
// TCP connection (Boost.Beast parses the answers), a WebSocket live client, and UDP sockets on
// the four ports P..P+3 of an RTP destination (spec/rtp.md). Link fapcast::transport (Asio's
// settings); Beast is header-only.
#include "fapcast/transport/asio.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fapcast::test {

namespace beast = boost::beast;
namespace http = boost::beast::http;
using tcp = boost::asio::ip::tcp;

struct HttpAnswer {
  int status = 0;    // 0: no answer was read
  std::string body;
  std::string error;  // what ended the exchange early
};

// Writes `raw` (one or more requests, bytes as they are) on a new connection to 127.0.0.1:port,
// then reads answers until `answers` have arrived, the server closes or `timeout` passes. A
// server that refuses a request before reading all of it may close while bytes are unsent: the
// write's error is ignored and what was answered is still read.
inline std::vector<HttpAnswer> http_exchange(std::uint16_t port, std::string_view raw, std::size_t answers = 1,
                                             std::chrono::milliseconds timeout = std::chrono::seconds(20)) {
  asio::io_context io;
  beast::tcp_stream stream(io);
  std::vector<HttpAnswer> out;
  beast::error_code ec;
  stream.expires_after(timeout);
  stream.socket().connect({asio::ip::make_address("127.0.0.1"), port}, ec);
  if (ec) return {HttpAnswer{0, {}, "connect: " + ec.message()}};
  beast::flat_buffer buffer;
  std::function<void()> read_one = [&] {
    auto parser = std::make_shared<http::response_parser<http::string_body>>();
    parser->body_limit(1 << 24);
    http::async_read(stream, buffer, *parser, [&, parser](beast::error_code e, std::size_t) {
      if (e) {
        if (out.empty()) out.push_back({0, {}, "read: " + e.message()});
        return;
      }
      const auto& r = parser->get();
      out.push_back({static_cast<int>(r.result_int()), r.body(), {}});
      if (out.size() < answers) read_one();
    });
  };
  asio::async_write(stream, asio::buffer(raw.data(), raw.size()), [](beast::error_code, std::size_t) {});
  read_one();
  io.run();
  return out;
}

// One request with a JSON body: "METHOD TARGET" with the bearer token (none when empty).
inline std::string json_request(std::string_view method, std::string_view target, std::string_view token,
                                std::string_view body) {
  std::string r = std::string(method) + " " + std::string(target) + " HTTP/1.1\r\nHost: 127.0.0.1\r\n";
  if (!token.empty()) r += "Authorization: Bearer " + std::string(token) + "\r\n";
  if (!body.empty())
    r += "Content-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) + "\r\n";
  return r + "\r\n" + std::string(body);
}

// A WebSocket live client of /v1/live?channel=CHANNEL (token in the Authorization header), on
// its own io_context: one thread uses it.
class DroppingLiveClient {
 public:
  DroppingLiveClient(std::uint16_t port, const std::string& token, const std::string& channel) : ws_(io_) {
    beast::get_lowest_layer(ws_).connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
    ws_.set_option(beast::websocket::stream_base::decorator([token](beast::websocket::request_type& req) {
      req.set(http::field::authorization, "Bearer " + token);
      req.set(http::field::sec_websocket_protocol, "fapcast.v1");
    }));
    ws_.handshake("127.0.0.1", "/v1/live?channel=" + channel);
  }
  // Reads one message within `timeout`; false when none came or the stream ended.
  bool read(std::string& message, bool& binary, std::chrono::milliseconds timeout) {
    beast::flat_buffer b;
    bool done = false;
    beast::error_code ec;
    ws_.async_read(b, [&](beast::error_code e, std::size_t) {
      ec = e;
      done = true;
    });
    io_.restart();
    io_.run_for(timeout);
    if (!done) {
      drop();  // cancels the read
      io_.restart();
      io_.run();
      return false;
    }
    if (ec) return false;
    binary = ws_.got_binary();
    message = beast::buffers_to_string(b.data());
    return true;
  }
  // Drops the connection without a close handshake (a client that goes away mid-stream).
  void drop() {
    beast::error_code ec;
    beast::get_lowest_layer(ws_).socket().shutdown(tcp::socket::shutdown_both, ec);
    beast::get_lowest_layer(ws_).socket().close(ec);
  }
  // The close handshake, then the connection closed.
  void close() {
    beast::get_lowest_layer(ws_).expires_after(std::chrono::seconds(5));
    bool done = false;
    ws_.async_close(beast::websocket::close_code::normal, [&](beast::error_code) { done = true; });
    io_.restart();
    io_.run_for(std::chrono::seconds(5));
    if (!done) drop();
    io_.restart();
    io_.run();
  }

 private:
  asio::io_context io_;
  beast::websocket::stream<beast::tcp_stream> ws_;
};

// UDP sockets bound on 127.0.0.1 at P, P+1, P+2, P+3 (animation RTP, its RTCP, audio RTP, its
// RTCP) for a free even P.
class RtpPorts {
 public:
  RtpPorts() {
    for (int attempt = 0; attempt < 64 && !ok_; ++attempt) {
      close_all();
      fds_[0] = bound(0);
      if (fds_[0] < 0) continue;
      sockaddr_in a{};
      socklen_t n = sizeof a;
      ::getsockname(fds_[0], reinterpret_cast<sockaddr*>(&a), &n);
      port_ = ntohs(a.sin_port);
      if (port_ % 2 != 0 || port_ > 65532) continue;
      ok_ = true;
      for (int i = 1; i < 4 && ok_; ++i) ok_ = (fds_[i] = bound(static_cast<std::uint16_t>(port_ + i))) >= 0;
    }
    if (!ok_) throw std::runtime_error("no four free UDP ports on loopback");
    for (const int fd : fds_) {
      const int size = 8 << 20;
      ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &size, sizeof size);
    }
  }
  ~RtpPorts() { close_all(); }
  RtpPorts(const RtpPorts&) = delete;
  RtpPorts& operator=(const RtpPorts&) = delete;

  std::uint16_t port() const { return port_; }
  std::string url() const { return "udp://127.0.0.1:" + std::to_string(port_); }
  int fd(int i) const { return fds_[static_cast<std::size_t>(i)]; }
  // Reads every datagram waiting on the four sockets; returns how many.
  std::size_t drain() {
    std::size_t n = 0;
    std::array<std::uint8_t, 2048> b;
    for (const int fd : fds_)
      while (::recv(fd, b.data(), b.size(), MSG_DONTWAIT) > 0) ++n;
    return n;
  }
  // Waits up to `timeout` for a datagram on P+i; its bytes, or nothing.
  std::optional<std::vector<std::uint8_t>> receive(int i, std::chrono::milliseconds timeout) {
    pollfd p{fd(i), POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(timeout.count())) <= 0) return std::nullopt;
    std::vector<std::uint8_t> b(2048);
    const auto got = ::recv(fd(i), b.data(), b.size(), 0);
    if (got < 0) return std::nullopt;
    b.resize(static_cast<std::size_t>(got));
    return b;
  }

 private:
  static int bound(std::uint16_t port) {
    const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd >= 0 && ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) return fd;
    if (fd >= 0) ::close(fd);
    return -1;
  }
  void close_all() {
    for (int& fd : fds_)
      if (fd >= 0) ::close(std::exchange(fd, -1));
  }
  std::array<int, 4> fds_{-1, -1, -1, -1};
  std::uint16_t port_ = 0;
  bool ok_ = false;
};

}  // namespace fapcast::test
