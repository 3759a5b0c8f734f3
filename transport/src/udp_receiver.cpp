#include "fapcast/transport/udp_receiver.hpp"

#include <array>

namespace fapcast {
namespace {
constexpr std::chrono::milliseconds kPollPeriod{5};  // how often held packets are re-examined
}

UdpReceiver::UdpReceiver(asio::io_context& io, udp::endpoint listen, ReceiverSocketOptions options)
    : io_(io), socket_(io), options_(std::move(options)) {
  std::error_code ec;
  open(listen, ec);
  if (ec) throw std::system_error(ec, "udp receiver on " + listen.address().to_string() + ":" +
                                          std::to_string(listen.port()));
}

UdpReceiver::UdpReceiver(asio::io_context& io, udp::endpoint listen, ReceiverSocketOptions options,
                         std::error_code& ec)
    : io_(io), socket_(io), options_(std::move(options)) {
  open(listen, ec);
}

void UdpReceiver::open(udp::endpoint listen, std::error_code& ec) {
  if (options_.srtp) srtp_.emplace(*options_.srtp, SrtpDirection::kReceive);
  boost::system::error_code bec;
  const auto group = listen.address();
  socket_.open(group.is_v4() ? udp::v4() : udp::v6(), bec);
  if (!bec && group.is_multicast()) socket_.set_option(udp::socket::reuse_address(true), bec);
  // Binding the group address (Linux) keeps datagrams of other groups on the port out.
  if (!bec) socket_.bind(listen, bec);
  if (!bec && group.is_multicast()) {
    if (group.is_v4() && options_.interface && options_.interface->is_v4())
      socket_.set_option(asio::ip::multicast::join_group(group.to_v4(), options_.interface->to_v4()),
                         bec);
    else
      socket_.set_option(asio::ip::multicast::join_group(group), bec);
  }
  ec = bec;
}

udp::endpoint UdpReceiver::local_endpoint() const {
  boost::system::error_code ec;
  return socket_.local_endpoint(ec);
}

std::uint64_t UdpReceiver::run(RtpStreamReceiver& stream, const ReceiveLimits& limits,
                               const std::function<void(ReceivedUnit&&)>& sink) {
  std::error_code ec;
  const auto filtered = run(stream, limits, sink, ec);
  if (ec) throw std::system_error(ec, "receive");
  return filtered;
}

std::uint64_t UdpReceiver::run(RtpStreamReceiver& stream, const ReceiveLimits& limits,
                               const std::function<void(ReceivedUnit&&)>& sink,
                               std::error_code& ec) {
  using Clock = RtpStreamReceiver::Clock;
  std::array<std::uint8_t, 65536> buffer;
  udp::endpoint from;
  std::vector<ReceivedUnit> units;
  std::uint64_t filtered = 0;
  std::uint64_t delivered = 0;
  bool pending = false;
  bool failed = false;
  const Clock::time_point start = Clock::now();
  Clock::time_point last_datagram = start;
  const auto drain = [&] {
    for (auto& u : units) {
      ++delivered;
      sink(std::move(u));
    }
    units.clear();
  };
  ec.clear();
  for (;;) {
    if (!pending) {
      pending = true;
      socket_.async_receive_from(
          asio::buffer(buffer), from, [&](const boost::system::error_code& error, std::size_t n) {
            pending = false;
            if (error) {
              if (error != asio::error::operation_aborted) {
                ec = error;
                failed = true;
              }
              return;
            }
            const Clock::time_point now = Clock::now();
            last_datagram = now;
            if (options_.source && from.address() != *options_.source) {
              ++filtered;
              return;
            }
            if (srtp_ && srtp_->unprotect_rtp({buffer.data(), n}, n)) return;  // refused and counted
            (void)stream.on_datagram({buffer.data(), n}, now, units);
          });
    }
    io_.restart();
    io_.run_for(kPollPeriod);
    const Clock::time_point now = Clock::now();
    stream.poll(now, units);
    drain();
    const bool done = failed || now - last_datagram >= limits.idle_timeout ||
                      (limits.max_duration && now - start >= *limits.max_duration) ||
                      delivered >= limits.max_units;
    if (done) break;
  }
  if (pending) {
    boost::system::error_code ignored;
    socket_.cancel(ignored);
    io_.restart();
    io_.run_for(std::chrono::milliseconds(100));  // lets the aborted handler finish
  }
  stream.flush(units);
  drain();
  return filtered;
}

}  // namespace fapcast
