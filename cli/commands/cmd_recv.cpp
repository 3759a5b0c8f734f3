// `fapcast recv udp://HOST:PORT -o OUT.fap|OUT.fba|OUT.json [--timeout SECONDS] [...]`: receives
// an RTP FAP stream (spec/rtp.md) until its sender says BYE or it falls silent, and writes the
// track atomically. The output's temporary file is created before listening (an output that
// cannot be written fails before the session, not after it); SIGINT and SIGTERM end the session
// and write what arrived. Argument parsing and the report only; receiving and decoding are
// transport functions.
#include "command.hpp"
#include "fap_output.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/transport/fba_track.hpp"
#include "fapcast/transport/timeline.hpp"
#include "fapcast/transport/track_file.hpp"
#include "fapcast/transport/srtp_key.hpp"
#include "fapcast/transport/udp_receiver.hpp"
#include "fapcast/transport/udp_url.hpp"

#include <csignal>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace {
using namespace fapcast;

struct RecvArgs {
  std::string url;
  std::string output;
  std::string player;
  double timeout_seconds = 5;
  std::string source;
  std::string interface;
  std::int64_t ssrc = -1;
  int payload_type = kDefaultFbaPayloadType;
  std::int64_t clock_rate = kDefaultSampleRate.hz;
  int reorder_ms = 40;
  double max_seconds = 3600;
  std::string srtp_key_file;
};

asio::ip::address address_option(const std::string& name, const std::string& text) {
  boost::system::error_code ec;
  const auto address = asio::ip::make_address(text, ec);
  if (ec) throw cli::UsageError(name + " " + text + ": not an IP address");
  return address;
}

void run_recv(const RecvArgs& a) {
  if (!track_format_of(a.output))
    throw cli::UsageError(a.output + ": expected a .fap, .fba or .json output");
  UdpUrl url;
  if (const auto ec = parse_udp_url(a.url, url)) throw cli::UsageError(a.url + ": " + ec.message());
  ReceiverSocketOptions socket;
  if (!a.source.empty()) socket.source = address_option("--source", a.source);
  if (!a.interface.empty()) socket.interface = address_option("--interface", a.interface);
  if (!a.srtp_key_file.empty()) socket.srtp = read_srtp_key_file(a.srtp_key_file);
  AtomicFile output(a.output);  // fails now, before listening, when the output cannot be written

  asio::io_context io;
  UdpReceiver receiver(io, resolve_udp_url(io, a.url), socket);
  asio::signal_set signals(io, SIGINT, SIGTERM);
  bool interrupted = false;
  signals.async_wait([&](const boost::system::error_code& ec, int) {
    if (ec) return;
    interrupted = true;
    receiver.stop();
  });

  ReceiverOptions options;
  options.payload_type = static_cast<std::uint8_t>(a.payload_type);
  if (a.ssrc >= 0) options.ssrc = static_cast<std::uint32_t>(a.ssrc);
  options.clock_rate = SampleRate{a.clock_rate};
  options.reorder_delay = std::chrono::milliseconds(a.reorder_ms);
  options.make_validator = make_fba_unit_validator;
  RtpStreamReceiver stream(options);
  ReceivedTrack track(SampleRate{a.clock_rate}, a.max_seconds);

  ReceiveLimits limits;
  limits.idle_timeout = std::chrono::milliseconds(static_cast<std::int64_t>(a.timeout_seconds * 1000));
  limits.done = [&] { return track.full(); };
  std::cerr << "fapcast: listening on " << receiver.local_endpoint() << " (RTCP on port "
            << receiver.local_endpoint().port() + 1 << ")\n";
  const ReceiveReport r =
      receiver.run(stream, limits, [&](ReceivedUnit&& u) { (void)track.add(u); });
  const auto& sr = stream.last_sender_report();
  track.finish(sr ? std::optional<std::uint32_t>(sr->packet_count) : std::nullopt,
               stream.anchor_sender_report());

  const auto& s = stream.stats();
  const auto& t = track.stats();
  std::ostringstream source;
  if (const auto ssrc = stream.locked_ssrc())
    source << "ssrc 0x" << std::hex << std::setw(8) << std::setfill('0') << *ssrc << std::dec
           << ", validated after " << options.min_sequential
           << " packets in sequence that decode (RFC 3550 A.1)";
  else
    source << "none validated";
  const std::string end = interrupted ? "interrupted by a signal"
                          : r.end == ReceiveEnd::kDone
                              ? "the track reached --max-seconds (" + std::to_string(track.max_frames()) + " frames)"
                              : to_string(r.end);
  std::cout << "source:    " << source.str() << "\n"
            << "packets:   " << s.accepted << " accepted, " << s.lost << " lost, " << s.late
            << " late, " << s.duplicates << " duplicate, " << s.skipped_waiting_intra
            << " skipped waiting for intra\n"
            << "refused:   " << s.malformed << " malformed, " << s.wrong_payload_type
            << " wrong payload type, " << s.foreign_ssrc << " foreign ssrc, "
            << s.probation_discarded << " discarded on probation, " << s.sequence_jumps
            << " sequence jumps, " << r.filtered << " from other addresses\n"
            << "rtcp:      " << r.rtcp_datagrams << " datagrams, " << s.sender_reports
            << " sender reports, " << s.byes << " bye, " << s.rtcp_refused + r.rtcp_filtered
            << " refused\n";
  if (const SrtpStats* srtp = receiver.srtp_stats())
    std::cout << "srtp:      " << srtp->unprotected_packets << " authenticated, " << srtp->auth_failed
              << " failed authentication, " << srtp->replayed << " replayed, " << srtp->malformed
              << " malformed (RTP and RTCP, refused before the parsers)\n";
  std::cout << "jitter:    " << stream.jitter_seconds() * 1000 << " ms (RFC 3550 A.8)\n"
            << "frames:    " << track.sequence().frames.size() << " from sender frame "
            << t.first_sender_frame << " (" << t.decoded << " decoded, " << t.leading_frames
            << " held before the first, " << t.held_frames << " held over gaps, "
            << t.trailing_frames << " held up to the sender's count)\n"
            << "discarded: " << t.decode_errors << " decode errors, " << t.timestamp_jumps
            << " timestamp jumps, " << t.over_limit << " over --max-seconds, "
            << t.frame_number_mismatches << " frame-number mismatches (placed by timestamp), "
            << t.discontinuities << " confirmed discontinuities, " << t.report_mismatches
            << " sender reports that fit no frame (a lost start not placed)\n"
            << "end:       " << end << "\n"
            << "received:  ";
  if (t.fapcast_units > 0) std::cout << t.fapcast_units << " units " << fba_profile_name(FbaProfile::kFapcast);
  if (t.fapcast_units > 0 && t.standard_units > 0) std::cout << ", ";
  if (t.standard_units > 0 || t.fapcast_units == 0) std::cout << t.standard_units << " units " << fba_profile_name(FbaProfile::kStandard);
  if (t.fap_quant >= 0)
    std::cout << ", fap_quant " << t.fap_quant << (t.fap_quant == 0 ? " (the values sent, losslessly)" : " (within half a step)");
  std::cout << "\n";
  if (track.sequence().frames.empty())
    throw std::runtime_error(a.url + ": recv-no-frames: no decodable frames arrived (" + end + ")");
  const TrackFileBytes out = track_file_bytes(
      a.output, track.sequence(),
      {.sample_rate = SampleRate{a.clock_rate}, .fap = cli::fap_write_options(a.player)});
  output.write(out.bytes);
  output.commit();
  cli::print_notes(a.output, out.notes);
}

const cli::Registration recv_command{"recv", [](CLI::App& app) {
  auto args = std::make_shared<RecvArgs>();
  auto* cmd = app.add_subcommand("recv", "Receive a FAP track over RTP/UDP and write it to a file");
  cmd->add_option("URL", args->url, "Listen on udp://HOST:PORT (a multicast group joins it; RTCP on PORT+1)")->required();
  cmd->add_option("-o,--output", args->output, "Output track: .fap, .fba or .json")->required();
  cli::add_player_option(cmd, args->player);
  cmd->add_option("--timeout", args->timeout_seconds, "Stop after this many seconds without an accepted packet")
      ->check(CLI::Range(0.01, 86400.0));
  cmd->add_option("--source", args->source, "Accept datagrams from this address only");
  cmd->add_option("--interface", args->interface, "Interface address to join a multicast group on");
  cmd->add_option("--ssrc", args->ssrc, "Accept this synchronisation source only (default: the first validated)")
      ->check(CLI::Range(std::int64_t{0}, std::int64_t{0xffffffff}));
  cmd->add_option("--payload-type", args->payload_type, "RTP payload type of the animation")
      ->check(CLI::Range(96, 127));
  cmd->add_option("--clock-rate", args->clock_rate, "RTP clock rate in Hz (the sender's audio rate)")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1000000}));
  cmd->add_option("--reorder-ms", args->reorder_ms, "Longest wait for a missing packet")
      ->check(CLI::Range(0, 10000));
  cmd->add_option("--max-seconds", args->max_seconds,
                  "Longest track kept, in seconds at the stream's frame rate (the session ends there)")
      ->check(CLI::Range(0.1, 86400.0));
  cmd->add_option("--srtp-key-file", args->srtp_key_file,
                  "Receive SRTP under the base64 master key in this file: spoofed, tampered and replayed packets are refused and counted");
  cmd->callback([args] { run_recv(*args); });
}};

}  // namespace
