// `fapcast recv udp://HOST:PORT -o OUT.fap|OUT.fba|OUT.json [--timeout SECONDS] [...]`: receives
// an RTP FAP stream (spec/rtp.md) until it falls silent and writes the track atomically.
// Argument parsing only; receiving and decoding are transport functions.
#include "command.hpp"

#include "fapcast/transport/fba_track.hpp"
#include "fapcast/transport/timeline.hpp"
#include "fapcast/transport/track_file.hpp"
#include "fapcast/transport/srtp_key.hpp"
#include "fapcast/transport/udp_receiver.hpp"
#include "fapcast/transport/udp_url.hpp"

#include <iostream>
#include <memory>

namespace {
using namespace fapcast;

struct RecvArgs {
  std::string url;
  std::string output;
  double timeout_seconds = 5;
  std::string source;
  std::string interface;
  std::int64_t ssrc = -1;
  int payload_type = kDefaultFbaPayloadType;
  std::int64_t clock_rate = kDefaultSampleRate;
  int reorder_ms = 40;
  double max_seconds = 3600;
  std::string srtp_key_file;
};

void run_recv(const RecvArgs& a) {
  if (!track_format_of(a.output))
    throw cli::UsageError(a.output + ": expected a .fap, .fba or .json output");
  asio::io_context io;
  ReceiverSocketOptions socket;
  if (!a.source.empty()) socket.source = asio::ip::make_address(a.source);
  if (!a.interface.empty()) socket.interface = asio::ip::make_address(a.interface);
  if (!a.srtp_key_file.empty()) socket.srtp = read_srtp_key_file(a.srtp_key_file);
  UdpReceiver receiver(io, resolve_udp_url(io, a.url), socket);

  ReceiverOptions options;
  options.payload_type = static_cast<std::uint8_t>(a.payload_type);
  if (a.ssrc >= 0) options.ssrc = static_cast<std::uint32_t>(a.ssrc);
  options.clock_rate = a.clock_rate;
  options.reorder_delay = std::chrono::milliseconds(a.reorder_ms);
  RtpStreamReceiver stream(options);
  ReceivedTrack track(a.clock_rate, static_cast<std::int64_t>(a.max_seconds * 120) + 1);

  ReceiveLimits limits;
  limits.idle_timeout = std::chrono::milliseconds(static_cast<std::int64_t>(a.timeout_seconds * 1000));
  std::cerr << "fapcast: listening on " << receiver.local_endpoint() << "\n";
  const std::uint64_t filtered =
      receiver.run(stream, limits, [&](ReceivedUnit&& u) { (void)track.add(u); });

  const auto& s = stream.stats();
  const auto& t = track.stats();
  std::cout << "packets:   " << s.accepted << " accepted, " << s.lost << " lost, " << s.late
            << " late, " << s.duplicates << " duplicate, " << s.skipped_waiting_intra
            << " skipped waiting for intra\n"
            << "refused:   " << s.malformed << " malformed, " << s.foreign_ssrc << " foreign ssrc, "
            << s.wrong_payload_type << " wrong payload type, " << s.sequence_jumps
            << " sequence jumps, " << filtered << " from other sources\n";
  if (const SrtpStats* srtp = receiver.srtp_stats())
    std::cout << "srtp:      " << srtp->unprotected_packets << " authenticated, " << srtp->auth_failed
              << " failed authentication, " << srtp->replayed << " replayed, " << srtp->malformed
              << " malformed\n";
  std::cout
            << "jitter:    " << stream.jitter_seconds() * 1000 << " ms (RFC 3550 A.8)\n"
            << "frames:    " << track.sequence().frames.size() << " (" << t.decoded << " decoded, "
            << t.held_frames << " held over gaps, " << t.decode_errors << " decode errors)\n";
  if (track.sequence().frames.empty())
    throw std::runtime_error(a.url + ": no decodable frames arrived before the timeout");
  write_track_file(a.output, track.sequence(), a.clock_rate);
}

const cli::Registration reg{"61-recv", [](CLI::App& app) {
  auto args = std::make_shared<RecvArgs>();
  auto* cmd = app.add_subcommand("recv", "Receive a FAP track over RTP/UDP and write it to a file");
  cmd->add_option("url", args->url, "Listen on udp://HOST:PORT (a multicast group joins it)")->required();
  cmd->add_option("-o,--output", args->output, "Output track: .fap, .fba or .json")->required();
  cmd->add_option("--timeout", args->timeout_seconds, "Stop after this many seconds without packets")
      ->check(CLI::Range(0.01, 86400.0));
  cmd->add_option("--source", args->source, "Accept datagrams from this address only");
  cmd->add_option("--interface", args->interface, "Interface address to join a multicast group on");
  cmd->add_option("--ssrc", args->ssrc, "Accept this synchronisation source only (default: the first)")
      ->check(CLI::Range(std::int64_t{0}, std::int64_t{0xffffffff}));
  cmd->add_option("--payload-type", args->payload_type, "RTP payload type of the animation")
      ->check(CLI::Range(96, 127));
  cmd->add_option("--clock-rate", args->clock_rate, "RTP clock rate in Hz (the sender's audio rate)")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1000000}));
  cmd->add_option("--reorder-ms", args->reorder_ms, "Longest wait for a missing packet")
      ->check(CLI::Range(0, 10000));
  cmd->add_option("--max-seconds", args->max_seconds, "Longest track kept (frames beyond are dropped)")
      ->check(CLI::Range(0.1, 86400.0));
  cmd->add_option("--srtp-key-file", args->srtp_key_file,
                  "Receive SRTP under the base64 master key in this file: spoofed, tampered and replayed packets are refused and counted");
  cmd->callback([args] { run_recv(*args); });
}};

}  // namespace
