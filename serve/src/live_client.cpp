#include "live_client.hpp"

#include "fapcast/serve/bearer_token.hpp"

namespace fapcast {

LiveClient::LiveClient(beast::tcp_stream stream, std::string channel, std::string peer, std::size_t queue_limit,
                       std::size_t send_buffer, Hooks hooks)
    : ws_(std::move(stream)),
      channel_(std::move(channel)),
      peer_(std::move(peer)),
      limit_(queue_limit),
      hooks_(std::move(hooks)),
      close_timer_(ws_.get_executor()) {
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().set_option(asio::socket_base::send_buffer_size(static_cast<int>(send_buffer)), ignored);
}

void LiveClient::accept(http::request<http::empty_body> request) {
  beast::get_lowest_layer(ws_).expires_never();  // the WebSocket's own timeouts from here on
  auto timeouts = websocket::stream_base::timeout::suggested(beast::role_type::server);
  timeouts.idle_timeout = std::chrono::seconds(30);
  timeouts.keep_alive_pings = true;  // an idle peer is pinged, a dead one closed
  ws_.set_option(timeouts);
  ws_.read_message_max(4096);
  const auto offered = request.find(http::field::sec_websocket_protocol);
  const bool subprotocol =
      offered != request.end() && offers_live_subprotocol(std::string_view(offered->value().data(), offered->value().size()));
  ws_.set_option(websocket::stream_base::decorator([subprotocol](websocket::response_type& res) {
    res.set(http::field::server, "fapcast");
    if (subprotocol) res.set(http::field::sec_websocket_protocol, std::string(kLiveSubprotocol));
  }));
  ws_.async_accept(request, [self = shared_from_this()](beast::error_code ec) {
    if (ec) return self->finish("handshake: " + ec.message());
    self->open_ = true;
    if (self->hooks_.on_open) self->hooks_.on_open(*self);
    self->read();
    self->write_next();
  });
}

void LiveClient::read() {
  ws_.async_read(incoming_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
    if (ec) {
      if (ec == websocket::error::closed) return self->finish("closed by the client");
      return self->finish(ec.message());
    }
    // Live clients only listen: anything they send is a protocol breach (spec/serve.md).
    self->incoming_.clear();
    self->close(websocket::close_code::policy_error, "live clients send nothing; use POST /v1/say");
  });
}

void LiveClient::send(std::shared_ptr<const std::string> message, bool binary) {
  if (finished_ || closing_) return;
  if (queue_.size() >= limit_) {
    close(websocket::close_code::policy_error,
          "slow-client: " + std::to_string(queue_.size()) + " messages waiting (limit " + std::to_string(limit_) + ")");
    return;
  }
  queue_.push_back({std::move(message), binary});
  if (open_) write_next();
}

void LiveClient::write_next() {
  if (writing_ || finished_) return;
  if (closing_) {
    writing_ = true;
    close_timer_.cancel();
    ws_.async_close(close_reason_, [self = shared_from_this()](beast::error_code) {
      self->writing_ = false;
      self->finish(std::string(self->close_reason_.reason.data(), self->close_reason_.reason.size()));
    });
    return;
  }
  if (queue_.empty()) return;
  writing_ = true;
  in_flight_ = std::move(queue_.front());  // kept alive until its write completes
  queue_.pop_front();
  ws_.binary(in_flight_.binary);
  ws_.async_write(asio::buffer(*in_flight_.bytes), [self = shared_from_this()](beast::error_code ec, std::size_t) {
    self->writing_ = false;
    self->in_flight_ = {};
    if (ec) return self->finish("write: " + ec.message());
    self->write_next();
  });
}

void LiveClient::close(websocket::close_code code, const std::string& reason) {
  if (closing_ || finished_) return;
  closing_ = true;
  queue_.clear();
  close_reason_ = websocket::close_reason(code, reason.substr(0, 120));  // a close reason is at most 123 bytes
  if (!open_) return finish(reason);
  if (writing_) {
    // The write in progress may be stuck on a peer that does not read: give it 1 s.
    close_timer_.expires_after(std::chrono::seconds(1));
    close_timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (ec) return;
      beast::error_code ignored;
      beast::get_lowest_layer(self->ws_).socket().close(ignored);
    });
    return;
  }
  write_next();
}

void LiveClient::abort() {
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().close(ignored);
}

void LiveClient::finish(const std::string& why) {
  if (finished_) return;
  finished_ = true;
  queue_.clear();
  close_timer_.cancel();
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().shutdown(tcp::socket::shutdown_both, ignored);
  beast::get_lowest_layer(ws_).socket().close(ignored);
  if (hooks_.on_close) hooks_.on_close(*this, closing_ ? std::string(close_reason_.reason.data(), close_reason_.reason.size()) : why);
  hooks_ = {};
}

}  // namespace fapcast
