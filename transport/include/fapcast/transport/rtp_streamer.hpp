#pragma once
// Sends an animation stream (FBA units, one per RTP packet) and optionally its audio (L16) as
// two RTP streams with RTCP sender reports, paced in real time against steady_clock with
// absolute deadlines (so no error accumulates), or as fast as possible.
// Ports: animation RTP at P, its RTCP at P+1, audio RTP at P+2, its RTCP at P+3 (RFC 3550 11).
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/transport/asio.hpp"
#include "fapcast/transport/media_unit.hpp"
#include "fapcast/transport/rtcp_sender_report.hpp"
#include "fapcast/transport/rtp_packet.hpp"
#include "fapcast/transport/udp_sender.hpp"
#include "fapcast/core/wav_file.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace fapcast {

// The numbering of one RTP stream: RFC 3550 wants the first sequence number and timestamp
// random; tests fix them.
struct RtpStreamIds {
  std::uint32_t ssrc = 0;
  std::uint16_t first_sequence = 0;
  std::uint32_t first_timestamp = 0;
  // Random ids from std::random_device.
  static RtpStreamIds random();
};

// "fapcast@HOSTNAME": the canonical name both streams of one sender report.
std::string default_cname();

struct StreamOptions {
  bool pace = true;                          // real time; false: as fast as the socket takes it
  SampleRate clock_rate{48'000};            // RTP clock of both streams (the audio rate)
  std::uint8_t animation_payload_type = kDefaultFbaPayloadType;
  std::uint8_t audio_payload_type = kDefaultL16PayloadType;
  RtpStreamIds animation_ids = RtpStreamIds::random();
  RtpStreamIds audio_ids = RtpStreamIds::random();
  std::chrono::milliseconds rtcp_interval{1000};  // between sender reports (0: none)
  std::string cname = default_cname();       // SDES CNAME of both streams (ties them together)
  SenderSocketOptions socket;
};

struct StreamCounts {
  std::uint32_t packets = 0;
  std::uint32_t payload_octets = 0;  // as RTCP counts them: payload only
  std::uint32_t sender_reports = 0;
};

struct StreamReport {
  StreamCounts animation;
  StreamCounts audio;
  std::chrono::nanoseconds late_total{0};  // summed lateness of paced sends past their deadline
};

// Builds the RTP packet of unit `index` of a stream (exposed for tests and the benchmark).
std::error_code pack_animation_packet(const MediaUnit& unit, std::size_t index,
                                      const RtpStreamIds& ids, std::uint8_t payload_type,
                                      std::vector<std::uint8_t>& out);

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
  UdpSender animation_rtp_;
  UdpSender animation_rtcp_;
  std::optional<UdpSender> audio_rtp_;
  std::optional<UdpSender> audio_rtcp_;
  udp::endpoint destination_;
};

}  // namespace fapcast
