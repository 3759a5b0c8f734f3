#include "fapcast/transport/paced_datagrams.hpp"

#include <algorithm>

namespace fapcast {

PacedSendReport send_paced(UdpSender& sender, std::span<const TimedDatagram> datagrams, bool pace, std::error_code& ec) {
  using Clock = std::chrono::steady_clock;
  PacedSendReport report;
  asio::io_context io;
  asio::steady_timer timer(io);
  const Clock::time_point start = Clock::now();
  for (const TimedDatagram& d : datagrams) {
    if (pace) {
      const Clock::time_point deadline = start + d.at;
      const Clock::time_point now = Clock::now();
      if (now < deadline) {
        timer.expires_at(deadline);
        boost::system::error_code wait_error;
        timer.wait(wait_error);
      } else {
        const auto late = std::chrono::duration_cast<std::chrono::nanoseconds>(now - deadline);
        report.late_total += late;
        report.late_max = std::max(report.late_max, late);
      }
    }
    sender.send(d.bytes, ec);
    if (ec) return report;
    ++report.sent;
  }
  return report;
}

}  // namespace fapcast
