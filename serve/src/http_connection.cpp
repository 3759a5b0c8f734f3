#include "http_connection.hpp"

#include "fapcast/serve/request_error.hpp"

#include <array>
#include <utility>
#include <sstream>

namespace fapcast {
namespace {

constexpr std::size_t kLingerBytes = 1024 * 1024;
constexpr std::chrono::seconds kLingerTime{1};

struct Lingering : std::enable_shared_from_this<Lingering> {
  Lingering(tcp::socket s, std::function<void()> closed)
      : socket(std::move(s)), timer(socket.get_executor()), on_closed(std::move(closed)) {}
  void start() {
    beast::error_code ignored;
    socket.shutdown(tcp::socket::shutdown_send, ignored);
    timer.expires_after(kLingerTime);
    timer.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (!ec) self->finish();
    });
    read();
  }
  void read() {
    socket.async_read_some(asio::buffer(scratch), [self = shared_from_this()](beast::error_code ec, std::size_t n) {
      self->discarded += n;
      if (ec || self->discarded >= kLingerBytes) return self->finish();
      self->read();
    });
  }
  void finish() {
    if (!socket.is_open()) return;  // the timer and the read both end it
    beast::error_code ignored;
    timer.cancel();
    socket.close(ignored);
    if (on_closed) std::exchange(on_closed, nullptr)();
  }
  tcp::socket socket;
  asio::steady_timer timer;
  std::function<void()> on_closed;
  std::array<char, 16 * 1024> scratch{};
  std::size_t discarded = 0;
};

}  // namespace

void linger_close(tcp::socket socket, std::function<void()> on_closed) {
  if (!socket.is_open()) {
    if (on_closed) on_closed();
    return;
  }
  std::make_shared<Lingering>(std::move(socket), std::move(on_closed))->start();
}

std::string redacted_target(std::string_view target) {
  std::string out(target);
  for (std::size_t at = out.find("token="); at != std::string::npos; at = out.find("token=", at + 1)) {
    if (at != 0 && out[at - 1] != '?' && out[at - 1] != '&') continue;
    const std::size_t end = out.find('&', at);
    out.replace(at + 6, (end == std::string::npos ? out.size() : end) - at - 6, "-");
  }
  return out;
}

HttpResponse make_response(http::status status, std::string body, std::string_view content_type, unsigned version) {
  HttpResponse res{status, version};
  res.set(http::field::server, "fapcast");
  res.set(http::field::content_type, std::string(content_type));
  res.set(http::field::cache_control, "no-store");
  res.set("X-Content-Type-Options", "nosniff");
  res.body() = std::move(body);
  res.prepare_payload();
  return res;
}

HttpConnection::HttpConnection(tcp::socket socket, std::size_t max_header_bytes, std::size_t max_body_bytes,
                               std::chrono::milliseconds request_timeout, std::chrono::milliseconds idle_timeout,
                               HttpHandler handler)
    : stream_(std::move(socket)),
      max_header_(max_header_bytes),
      max_body_(max_body_bytes),
      request_timeout_(request_timeout),
      idle_timeout_(idle_timeout),
      handler_(std::move(handler)) {
  beast::error_code ec;
  const auto remote = stream_.socket().remote_endpoint(ec);
  std::ostringstream p;
  if (!ec) p << remote;
  peer_ = ec ? std::string("?") : p.str();
}

void HttpConnection::start() { read_head(); }

void HttpConnection::read_head() {
  parser_.emplace();
  parser_->header_limit(static_cast<std::uint32_t>(max_header_));
  parser_->body_limit(max_body_);
  request_line_.clear();
  // The first request must arrive whole within the request timeout; a kept-alive connection
  // may idle longer between requests.
  stream_.expires_after(first_ ? request_timeout_ : idle_timeout_);
  first_ = false;
  http::async_read_header(stream_, buffer_, *parser_,
                          [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_head(ec); });
}

void HttpConnection::on_head(beast::error_code ec) {
  request_start_ = std::chrono::steady_clock::now();
  if (ec == http::error::end_of_stream || ec == beast::error::timeout || ec == asio::error::connection_reset ||
      ec == asio::error::operation_aborted || ec == asio::error::eof)
    return done();
  if (ec == http::error::header_limit)
    return refuse(http::status::request_header_fields_too_large, "header-too-large",
                  "the request line and headers exceed " + std::to_string(max_header_) + " bytes");
  if (ec == http::error::body_limit)
    return refuse(http::status::payload_too_large, "body-too-large",
                  "Content-Length exceeds the limit of " + std::to_string(max_body_) + " bytes");
  if (ec) return refuse(http::status::bad_request, "http-malformed", ec.message());
  const auto& head = parser_->get();
  request_line_ = std::string(head.method_string()) + " " + redacted_target(std::string_view(head.target().data(), head.target().size()).substr(0, 200));
  stream_.expires_after(request_timeout_);
  bool upgrade = false;
  if (auto refusal = handler_.on_head(*this, head, upgrade)) {
    close_after_ = true;  // the body (if any) is not read: the connection cannot go on
    respond(std::move(*refusal));
    return;
  }
  if (upgrade) return;  // a WebSocket client owns the socket now
  const auto expect = head.find(http::field::expect);
  if (expect != head.end() && beast::iequals(expect->value(), "100-continue")) {
    auto cont = std::make_shared<http::response<http::empty_body>>(http::status::continue_, head.version());
    http::async_write(stream_, *cont, [self = shared_from_this(), cont](beast::error_code e, std::size_t) {
      if (e) return self->done();
      self->read_body();
    });
    return;
  }
  read_body();
}

void HttpConnection::read_body() {
  http::async_read(stream_, buffer_, *parser_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
    if (ec == http::error::body_limit)
      return self->refuse(http::status::payload_too_large, "body-too-large",
                          "the body exceeds the limit of " + std::to_string(self->max_body_) + " bytes");
    if (ec) return self->done();
    self->keep_alive_ = self->parser_->get().keep_alive();
    HttpRequest request = self->parser_->release();
    self->handler_.on_request(*self, std::move(request));
  });
}

void HttpConnection::refuse(http::status status, const std::string& rule, const std::string& detail) {
  close_after_ = true;
  if (handler_.on_refused) handler_.on_refused(static_cast<int>(status));
  respond(make_response(status, request_error_body(RequestError(static_cast<int>(status), rule, detail)),
                        "application/json", 11),
          rule);
}

void HttpConnection::respond(HttpResponse response, const std::string& note) {
  if (closed_ || released_) return;
  response.keep_alive(keep_alive_ && !close_after_);
  response_ = std::make_shared<HttpResponse>(std::move(response));
  // A deferred answer (202 once speaking has started) comes after the head's deadline: the
  // answer gets a deadline of its own.
  stream_.expires_after(request_timeout_);
  if (handler_.log) {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - request_start_).count();
    std::ostringstream line;
    line.setf(std::ios::fixed);
    line.precision(1);
    line << peer_ << " \"" << (request_line_.empty() ? std::string("-") : request_line_) << "\" "
         << response_->result_int() << " " << ms << " ms";
    if (!note.empty()) line << " " << note;
    handler_.log(line.str());
  }
  http::async_write(stream_, *response_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
    self->response_.reset();
    if (ec) return self->done();
    if (self->close_after_ || !self->keep_alive_) {
      // The peer may still be sending a body that was not read (a refusal on the head).
      self->stream_.expires_never();
      if (self->handler_.close_lingering) self->handler_.close_lingering(self->stream_.release_socket());
      else linger_close(self->stream_.release_socket());
      return self->done();
    }
    self->read_head();
  });
}

beast::tcp_stream HttpConnection::release_stream() {
  released_ = true;
  beast::tcp_stream out = std::move(stream_);
  done();
  return out;
}

void HttpConnection::close() {
  if (closed_ || released_) return;
  beast::error_code ignored;
  stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
  stream_.close();
}

void HttpConnection::done() {
  if (closed_) return;
  closed_ = true;
  if (!released_) {
    beast::error_code ignored;
    stream_.socket().close(ignored);
  }
  if (handler_.on_closed) handler_.on_closed(*this);
}

}  // namespace fapcast
