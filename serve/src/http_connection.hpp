#pragma once
// One HTTP/1.1 connection: reads a request head (bounded size, bounded time), lets the server
// decide on the head alone (route, Origin, token, limits) before any body is read, then reads
// the body (bounded) or hands the socket to a WebSocket client. Answers are written one at a
// time; an answer may be deferred (POST /v1/say answers once speaking has started).
#include "beast.hpp"

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace fapcast {

class HttpConnection;

using HttpResponse = http::response<http::string_body>;
using HttpRequest = http::request<http::string_body>;

// What the server does with a connection's requests.
struct HttpHandler {
  // After the head: an answer now (a refusal; the connection closes after it), or nothing to go
  // on (read the body, or the handler took the socket for a WebSocket).
  std::function<std::optional<HttpResponse>(HttpConnection&, const http::request_header<>& head, bool& upgrade)> on_head;
  // After the body: the handler answers through respond(), now or later.
  std::function<void(HttpConnection&, HttpRequest request)> on_request;
  std::function<void(const std::string& line)> log;
  // A request the connection refuses itself (431, 413, 400 http-malformed): its status, to count.
  std::function<void(int status)> on_refused;
  std::function<void(HttpConnection&)> on_closed;
  // Closes the socket after a refusal (linger_close by default): the server's, to count it.
  std::function<void(tcp::socket)> close_lingering;
};

class HttpConnection : public std::enable_shared_from_this<HttpConnection> {
 public:
  HttpConnection(tcp::socket socket, std::size_t max_header_bytes, std::size_t max_body_bytes,
                 std::chrono::milliseconds request_timeout, std::chrono::milliseconds idle_timeout, HttpHandler handler);

  void start();
  // Writes the answer to the request being handled; `note` goes to its log line.
  void respond(HttpResponse response, const std::string& note = {});
  // The socket, for a WebSocket upgrade (the connection is done with it afterwards).
  beast::tcp_stream release_stream();
  // Closes the socket now (shutdown).
  void close();

  const std::string& peer() const { return peer_; }
  // "METHOD TARGET" of the request being handled.
  const std::string& request_line() const { return request_line_; }
  std::chrono::steady_clock::time_point request_start() const { return request_start_; }

 private:
  void read_head();
  void on_head(beast::error_code ec);
  void read_body();
  void refuse(http::status status, const std::string& rule, const std::string& detail);
  void done();

  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::size_t max_header_, max_body_;
  std::chrono::milliseconds request_timeout_, idle_timeout_;
  HttpHandler handler_;
  std::string peer_, request_line_;
  std::chrono::steady_clock::time_point request_start_{};
  std::shared_ptr<HttpResponse> response_;
  bool keep_alive_ = false, close_after_ = false, released_ = false, closed_ = false, first_ = true;
};

// Closes a socket whose peer may still be sending (a refusal before the body was read): shuts
// down the sending side, then reads and discards what arrives until the peer closes, 1 MiB or
// 1 s, whichever comes first, and only then closes. Closing with unread data would make the
// kernel reset the connection, and a client then reports "connection reset" instead of the answer.
// `on_closed`, when given, is called once the socket is closed (on its executor).
void linger_close(tcp::socket socket, std::function<void()> on_closed = {});

// The target as logged: the value of a ?token= parameter replaced by "-" (a secret stays out of logs).
std::string redacted_target(std::string_view target);

// A response with a JSON (or other) body and the headers every answer carries.
HttpResponse make_response(http::status status, std::string body, std::string_view content_type, unsigned version);

}  // namespace fapcast
