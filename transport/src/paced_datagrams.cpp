#include "fapcast/transport/paced_datagrams.hpp"

#include <algorithm>

#include "wait_until.hpp"

namespace fapcast {

PacedSendReport send_paced(UdpSender& sender, std::span<const TimedDatagram> datagrams, bool pace, std::error_code& ec) {
  using Clock = std::chrono::steady_clock;
  PacedSendReport report;
  asio::io_context io;
  asio::steady_timer timer(io);
  const Clock::time_point start = Clock::now();
  for (const TimedDatagram& d : datagrams) {
    if (pace) {
      const auto late = std::chrono::duration_cast<std::chrono::nanoseconds>(detail::wait_until(timer, start + d.at));
      report.late_total += late;
      report.late_max = std::max(report.late_max, late);
    }
    sender.send(d.bytes, ec);
    if (ec) return report;
    ++report.sent;
  }
  return report;
}

}  // namespace fapcast
