#pragma once
// Datagrams sent to one UDP destination at given instants of a timeline, paced in real time against
// steady_clock (the first at the moment of the call): the live stream of a rig (VMC over OSC,
// spec/rigs.md) or anything else that is one datagram per instant.
#include <chrono>
#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

#include "fapcast/transport/udp_sender.hpp"

namespace fapcast {

struct TimedDatagram {
  std::chrono::nanoseconds at;        // from the start of the stream, non-decreasing
  std::vector<std::uint8_t> bytes;
};

struct PacedSendReport {
  std::int64_t sent = 0;
  std::chrono::nanoseconds late_total{0};  // summed lateness of sends after their instant
  std::chrono::nanoseconds late_max{0};
};

// Sends every datagram at steady start + at (or at once when `pace` is false). Stops at the first
// send error, reported in `ec`, with what was sent so far.
PacedSendReport send_paced(UdpSender& sender, std::span<const TimedDatagram> datagrams, bool pace,
                           std::error_code& ec);

}  // namespace fapcast
