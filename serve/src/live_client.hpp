#pragma once
// One live WebSocket client (spec/serve.md, "The live stream"): receives, never sends data. Its
// outgoing messages wait in a queue of at most ServeLimits::client_queue_frames; a client that
// lets it fill (a slow network, a stalled tab) is dropped with the close reason
// "slow-client: ..." rather than buffered for. Writes are one at a time (Beast's rule); a
// close waits for the write in progress, and a write that does not finish in 1 s closes the
// socket under it.
#include "beast.hpp"

#include <deque>
#include <functional>
#include <memory>
#include <string>

namespace fapcast {

class LiveClient : public std::enable_shared_from_this<LiveClient> {
 public:
  struct Hooks {
    std::function<void(LiveClient&)> on_open;   // accepted: greet it, add it to its channel
    std::function<void(LiveClient&, const std::string& why)> on_close;  // gone (once)
  };
  // `send_buffer`: the socket's SO_SNDBUF (fixed, so that the kernel cannot grow what it holds
  // for a client that does not read).
  LiveClient(beast::tcp_stream stream, std::string channel, std::string peer, std::size_t queue_limit,
             std::size_t send_buffer, Hooks hooks);

  // Completes the upgrade of `request` (already authenticated): answers "fapcast.v1" when the
  // client offers it.
  void accept(http::request<http::empty_body> request);
  // Queues one message; drops the client when its queue is full.
  void send(std::shared_ptr<const std::string> message, bool binary);
  // Closes with `code` and `reason` (after the write in progress).
  void close(websocket::close_code code, const std::string& reason);
  // Closes the socket now (the end of a shutdown that waited long enough).
  void abort();

  const std::string& channel() const { return channel_; }
  const std::string& peer() const { return peer_; }
  bool open() const { return open_ && !closing_; }
  std::size_t queued() const { return queue_.size(); }

 private:
  struct Message {
    std::shared_ptr<const std::string> bytes;
    bool binary = false;
  };
  void read();
  void write_next();
  void finish(const std::string& why);
  websocket::stream<beast::tcp_stream> ws_;
  std::string channel_, peer_;
  std::size_t limit_;
  Hooks hooks_;
  std::deque<Message> queue_;  // waiting, not counting the one being written
  Message in_flight_;
  beast::flat_buffer incoming_;
  bool open_ = false, writing_ = false, closing_ = false, finished_ = false;
  websocket::close_reason close_reason_;
  asio::steady_timer close_timer_;
};

}  // namespace fapcast
