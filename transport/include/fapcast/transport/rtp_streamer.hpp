#pragma once
// Sends a finished animation stream (FBA units, one per RTP packet) and optionally its audio
// (L16) through an RtpSender, paced in real time against steady_clock with absolute deadlines
// (so no error accumulates), or as fast as possible, with sender reports at a fixed interval.
#include "fapcast/transport/rtp_sender.hpp"
#include "fapcast/core/wav_file.hpp"

#include <chrono>
#include <cstdint>
#include <system_error>
#include <vector>

namespace fapcast {

struct StreamOptions : RtpSenderOptions {
  bool pace = true;                          // real time; false: as fast as the socket takes it
  SampleRate clock_rate{48'000};             // RTP clock of both streams (the audio rate)
  std::chrono::milliseconds rtcp_interval{1000};  // between sender reports (0: none)
};

struct StreamReport {
  StreamCounts animation;
  StreamCounts audio;
  std::chrono::nanoseconds late_total{0};  // summed lateness of paced sends past their deadline
};

class RtpStreamer {
 public:
  // Opens the sockets towards `destination` (its port is P). Throws std::system_error.
  RtpStreamer(asio::io_context& io, udp::endpoint destination, StreamOptions options);

  // Sends `animation` (sorted by sample) and, when given, `audio` (whose rate must equal
  // options.clock_rate). Blocks until the last packet is sent. Throws std::system_error.
  StreamReport run(const std::vector<MediaUnit>& animation, const Audio* audio = nullptr);
  StreamReport run(const std::vector<MediaUnit>& animation, const Audio* audio,
                   std::error_code& ec);

 private:
  asio::io_context& io_;
  StreamOptions options_;
  udp::endpoint destination_;
};

}  // namespace fapcast
