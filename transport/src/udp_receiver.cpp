#include "fapcast/transport/udp_receiver.hpp"

#include <array>

namespace fapcast {
namespace {
constexpr std::chrono::milliseconds kPollPeriod{5};  // how often held packets are re-examined
constexpr int kPortPairTries = 32;                   // ephemeral RTP ports tried for a free P+1
}

const char* to_string(ReceiveEnd end) {
  switch (end) {
    case ReceiveEnd::kIdle: return "idle timeout";
    case ReceiveEnd::kBye: return "the source sent BYE";
    case ReceiveEnd::kMaxDuration: return "maximum duration";
    case ReceiveEnd::kMaxUnits: return "maximum units";
    case ReceiveEnd::kDone: return "done";
    case ReceiveEnd::kStopped: return "stopped";
    case ReceiveEnd::kSocketError: return "socket error";
  }
  return "?";
}

UdpReceiver::UdpReceiver(asio::io_context& io, udp::endpoint listen, ReceiverSocketOptions options)
    : io_(io), socket_(io), rtcp_socket_(io), options_(std::move(options)) {
  std::error_code ec;
  open(listen, ec);
  if (ec) throw std::system_error(ec, "udp receiver on " + listen.address().to_string() + ":" +
                                          std::to_string(listen.port()));
}

UdpReceiver::UdpReceiver(asio::io_context& io, udp::endpoint listen, ReceiverSocketOptions options,
                         std::error_code& ec)
    : io_(io), socket_(io), rtcp_socket_(io), options_(std::move(options)) {
  open(listen, ec);
}

void UdpReceiver::open_socket(udp::socket& socket, udp::endpoint at, boost::system::error_code& ec) {
  const auto group = at.address();
  socket.open(group.is_v4() ? udp::v4() : udp::v6(), ec);
  if (!ec && group.is_multicast()) socket.set_option(udp::socket::reuse_address(true), ec);
  // Binding the group address (Linux) keeps datagrams of other groups on the port out.
  if (!ec) socket.bind(at, ec);
  if (!ec && group.is_multicast()) {
    if (group.is_v4() && options_.interface && options_.interface->is_v4())
      socket.set_option(asio::ip::multicast::join_group(group.to_v4(), options_.interface->to_v4()),
                        ec);
    else
      socket.set_option(asio::ip::multicast::join_group(group), ec);
  }
  if (ec) {
    boost::system::error_code ignored;
    socket.close(ignored);
  }
}

void UdpReceiver::open(udp::endpoint listen, std::error_code& ec) {
  if (options_.srtp) srtp_.emplace(*options_.srtp, SrtpDirection::kReceive);
  boost::system::error_code bec;
  if (!options_.rtcp) {
    open_socket(socket_, listen, bec);
    ec = bec;
    return;
  }
  if (listen.port() == 65535) {
    ec = std::make_error_code(std::errc::invalid_argument);  // no P+1 for RTCP
    return;
  }
  const int tries = listen.port() == 0 ? kPortPairTries : 1;
  for (int i = 0; i < tries; ++i) {
    open_socket(socket_, listen, bec);
    if (bec) break;
    const std::uint16_t port = socket_.local_endpoint(bec).port();
    if (bec) break;
    if (port == 65535) {
      socket_.close(bec);
      continue;
    }
    open_socket(rtcp_socket_, {listen.address(), static_cast<std::uint16_t>(port + 1)}, bec);
    if (!bec) break;
    boost::system::error_code ignored;
    socket_.close(ignored);
  }
  ec = bec;
}

udp::endpoint UdpReceiver::local_endpoint() const {
  boost::system::error_code ec;
  return socket_.local_endpoint(ec);
}

ReceiveReport UdpReceiver::run(RtpStreamReceiver& stream, const ReceiveLimits& limits,
                               const std::function<void(ReceivedUnit&&)>& sink) {
  std::error_code ec;
  const auto report = run(stream, limits, sink, ec);
  if (ec) throw std::system_error(ec, "receive");
  return report;
}

ReceiveReport UdpReceiver::run(RtpStreamReceiver& stream, const ReceiveLimits& limits,
                               const std::function<void(ReceivedUnit&&)>& sink,
                               std::error_code& ec) {
  using Clock = RtpStreamReceiver::Clock;
  std::array<std::uint8_t, 65536> buffer;
  std::array<std::uint8_t, 2048> rtcp_buffer;
  udp::endpoint from;
  udp::endpoint rtcp_from;
  std::optional<asio::ip::address> source_address;  // where the accepted RTP comes from
  std::vector<ReceivedUnit> units;
  ReceiveReport report;
  std::uint64_t delivered = 0;
  bool pending = false;
  bool rtcp_pending = false;
  bool failed = false;
  const Clock::time_point start = Clock::now();
  Clock::time_point last_accepted = start;
  const auto drain = [&] {
    for (auto& u : units) {
      ++delivered;
      sink(std::move(u));
    }
    units.clear();
  };
  const auto fail = [&](const boost::system::error_code& error) {
    if (error == asio::error::operation_aborted) return;
    ec = error;
    failed = true;
  };
  ec.clear();
  stop_ = false;
  for (;;) {
    if (!pending) {
      pending = true;
      socket_.async_receive_from(
          asio::buffer(buffer), from, [&](const boost::system::error_code& error, std::size_t n) {
            pending = false;
            if (error) return fail(error);
            const Clock::time_point now = Clock::now();
            if (options_.source && from.address() != *options_.source) {
              ++report.filtered;
              return;
            }
            // SRTP first: a packet without the key's tag, or one already received, is refused
            // (counted in srtp_stats()) before the RTP parser and the source validation see it.
            std::size_t length = n;
            if (srtp_ && srtp_->unprotect_rtp({buffer.data(), n}, length)) return;
            // Only packets of the validated source feed the idle timer: a decodable packet held
            // on probation is not yet accepted (a stream of one-packet sources would keep it alive).
            const std::uint64_t accepted_before = stream.stats().accepted;
            if (!stream.on_datagram({buffer.data(), length}, now, units) && stream.stats().accepted > accepted_before) {
              last_accepted = now;
              if (stream.locked_ssrc()) source_address = from.address();
            }
          });
    }
    if (rtcp_socket_.is_open() && !rtcp_pending) {
      rtcp_pending = true;
      rtcp_socket_.async_receive_from(
          asio::buffer(rtcp_buffer), rtcp_from,
          [&](const boost::system::error_code& error, std::size_t n) {
            rtcp_pending = false;
            if (error) return fail(error);
            ++report.rtcp_datagrams;
            // RTCP is taken only from the address the validated source's RTP comes from.
            if (!source_address || rtcp_from.address() != *source_address) {
              ++report.rtcp_filtered;
              return;
            }
            std::size_t length = n;
            if (srtp_ && srtp_->unprotect_rtcp({rtcp_buffer.data(), n}, length)) return;  // counted
            (void)stream.on_rtcp({rtcp_buffer.data(), length}, Clock::now());
          });
    }
    // One handler at most, then re-arm: with both sockets waiting, run_for would sit out the
    // whole period after each datagram and the kernel's buffer would overflow under a burst.
    io_.restart();
    io_.run_one_for(kPollPeriod);
    const Clock::time_point now = Clock::now();
    stream.poll(now, units);
    drain();
    std::optional<ReceiveEnd> end;
    if (failed) end = ReceiveEnd::kSocketError;
    else if (stop_) end = ReceiveEnd::kStopped;
    else if (limits.stop_on_bye && stream.source_left(now)) end = ReceiveEnd::kBye;
    else if (limits.done && limits.done()) end = ReceiveEnd::kDone;
    else if (delivered >= limits.max_units) end = ReceiveEnd::kMaxUnits;
    else if (limits.max_duration && now - start >= *limits.max_duration) end = ReceiveEnd::kMaxDuration;
    else if (now - last_accepted >= limits.idle_timeout) end = ReceiveEnd::kIdle;
    if (end) {
      report.end = *end;
      break;
    }
  }
  if (pending || rtcp_pending) {
    boost::system::error_code ignored;
    socket_.cancel(ignored);
    if (rtcp_socket_.is_open()) rtcp_socket_.cancel(ignored);
    io_.restart();
    io_.run_for(std::chrono::milliseconds(100));  // lets the aborted handlers finish
  }
  stream.flush(units);
  drain();
  return report;
}

}  // namespace fapcast
