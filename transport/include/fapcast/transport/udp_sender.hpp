#pragma once
// A UDP socket that sends datagrams to one destination, unicast or multicast.
#include "fapcast/transport/asio.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <system_error>

namespace fapcast {

struct SenderSocketOptions {
  std::optional<int> ttl;                             // hops (multicast TTL or unicast hop limit)
  std::optional<asio::ip::address> interface;         // outgoing interface for multicast (IPv4 address)
  bool multicast_loopback = true;                     // deliver our multicast to local listeners
};

class UdpSender {
 public:
  // Opens a socket of the destination's family on an ephemeral port and applies the options.
  // Throws std::system_error when the socket cannot be opened or an option is refused.
  UdpSender(asio::io_context& io, udp::endpoint destination, SenderSocketOptions options = {});
  UdpSender(asio::io_context& io, udp::endpoint destination, SenderSocketOptions options,
            std::error_code& ec);

  // Sends one datagram; throws std::system_error on failure.
  void send(std::span<const std::uint8_t> datagram);
  // Sends one datagram; reports failure in `ec`.
  void send(std::span<const std::uint8_t> datagram, std::error_code& ec);

  udp::endpoint destination() const { return destination_; }
  udp::endpoint local_endpoint() const;

 private:
  void open(const SenderSocketOptions& options, std::error_code& ec);
  udp::socket socket_;
  udp::endpoint destination_;
};

}  // namespace fapcast
