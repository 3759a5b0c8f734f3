#pragma once
// A UDP socket that feeds one RtpStreamReceiver: binds (and joins a multicast group when the
// address is one), filters by source address, polls the reorder buffer, and stops after a
// stretch with no datagrams. Every wait is bounded.
#include "fapcast/transport/asio.hpp"
#include "fapcast/transport/rtp_stream_receiver.hpp"
#include "fapcast/transport/srtp_key.hpp"
#include "fapcast/transport/srtp_session.hpp"

#include <chrono>
#include <functional>
#include <optional>
#include <system_error>

namespace fapcast {

struct ReceiverSocketOptions {
  std::optional<asio::ip::address> source;     // accept datagrams from this address only
  std::optional<asio::ip::address> interface;  // interface to join a multicast group on (IPv4)
  // Set: datagrams are SRTP; each is authenticated and decrypted before the stream sees it, and
  // refused (counted in srtp_stats()) when spoofed, tampered with or replayed.
  std::optional<SrtpMasterKey> srtp;
};

struct ReceiveLimits {
  std::chrono::milliseconds idle_timeout{5000};  // stop after this long without a datagram
  std::optional<std::chrono::milliseconds> max_duration;  // stop after this long regardless
  std::uint64_t max_units = UINT64_MAX;                   // stop after delivering this many
};

class UdpReceiver {
 public:
  // Binds `listen` (port 0: the system picks one; a multicast address: joins that group).
  // Throws std::system_error when the socket cannot be bound or the group not joined.
  UdpReceiver(asio::io_context& io, udp::endpoint listen, ReceiverSocketOptions options = {});
  UdpReceiver(asio::io_context& io, udp::endpoint listen, ReceiverSocketOptions options,
              std::error_code& ec);

  udp::endpoint local_endpoint() const;
  // SRTP's counts when the options carry a key, else null.
  const SrtpStats* srtp_stats() const { return srtp_ ? &srtp_->stats() : nullptr; }

  // Receives into `stream` until a limit is reached, calling `sink` for each unit in order, then
  // flushes the stream. Runs the io_context given at construction. Returns datagrams refused by
  // the source filter. Throws std::system_error on a socket failure.
  std::uint64_t run(RtpStreamReceiver& stream, const ReceiveLimits& limits,
                    const std::function<void(ReceivedUnit&&)>& sink);
  std::uint64_t run(RtpStreamReceiver& stream, const ReceiveLimits& limits,
                    const std::function<void(ReceivedUnit&&)>& sink, std::error_code& ec);

 private:
  void open(udp::endpoint listen, std::error_code& ec);
  asio::io_context& io_;
  udp::socket socket_;
  ReceiverSocketOptions options_;
  std::optional<SrtpSession> srtp_;
};

}  // namespace fapcast
