#include "fapcast/transport/udp_sender.hpp"

namespace fapcast {

UdpSender::UdpSender(asio::io_context& io, udp::endpoint destination, SenderSocketOptions options)
    : socket_(io), destination_(destination) {
  std::error_code ec;
  open(options, ec);
  if (ec) throw std::system_error(ec, "udp sender to " + destination.address().to_string());
}

UdpSender::UdpSender(asio::io_context& io, udp::endpoint destination, SenderSocketOptions options,
                     std::error_code& ec)
    : socket_(io), destination_(destination) {
  open(options, ec);
}

void UdpSender::open(const SenderSocketOptions& options, std::error_code& ec) {
  boost::system::error_code bec;
  const bool v4 = destination_.address().is_v4();
  socket_.open(v4 ? udp::v4() : udp::v6(), bec);
  if (!bec && destination_.address().is_multicast()) {
    if (options.ttl) socket_.set_option(asio::ip::multicast::hops(*options.ttl), bec);
    if (!bec) socket_.set_option(asio::ip::multicast::enable_loopback(options.multicast_loopback), bec);
    if (!bec && options.interface && options.interface->is_v4() && v4)
      socket_.set_option(asio::ip::multicast::outbound_interface(options.interface->to_v4()), bec);
  } else if (!bec && options.ttl) {
    socket_.set_option(asio::ip::unicast::hops(*options.ttl), bec);
  }
  ec = bec;
}

void UdpSender::send(std::span<const std::uint8_t> datagram) {
  std::error_code ec;
  send(datagram, ec);
  if (ec) throw std::system_error(ec, "send to " + destination_.address().to_string());
}

void UdpSender::send(std::span<const std::uint8_t> datagram, std::error_code& ec) {
  boost::system::error_code bec;
  socket_.send_to(asio::buffer(datagram.data(), datagram.size()), destination_, 0, bec);
  ec = bec;
}

udp::endpoint UdpSender::local_endpoint() const {
  boost::system::error_code ec;
  return socket_.local_endpoint(ec);
}

}  // namespace fapcast
