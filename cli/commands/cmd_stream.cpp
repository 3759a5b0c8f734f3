// `fapcast stream IN.fap|IN.fba|IN.json [--wav IN.wav] -o udp://HOST:PORT [...]`: sends a FAP
// track as RTP (spec/rtp.md), optionally with its audio as L16, paced in real time. Argument
// parsing only; reading, encoding and sending are transport functions.
#include "command.hpp"

#include "fapcast/transport/fba_track.hpp"
#include "fapcast/transport/rtp_streamer.hpp"
#include "fapcast/transport/srtp_key.hpp"
#include "fapcast/transport/timeline.hpp"
#include "fapcast/transport/track_file.hpp"
#include "fapcast/transport/udp_url.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/fba/fba_file.hpp"
#include "fapcast/fba/fba_quantiser.hpp"

#include <algorithm>
#include <iostream>
#include <memory>

namespace {
using namespace fapcast;

struct StreamArgs {
  std::string input;
  std::string wav;
  std::string to;
  bool no_pace = false;
  int ttl = -1;
  std::string interface;
  bool no_loopback = false;
  int iperiod = 25;
  std::string profile = "auto";
  int quant = -1;  // -1: chosen (see fba_choice)
  int payload_type = kDefaultFbaPayloadType;
  int audio_payload_type = kDefaultL16PayloadType;
  int rtcp_ms = 1000;
  std::string srtp_key_file;
};

// What the stream carries (spec/rtp.md §2): by default the values sent, losslessly: the standard
// syntax at fap_quant 0 where it codes every value, else the fapcast profile. `--profile
// standard` without --quant: fap_quant 0 where it can, else the smallest that codes every value
// (within half a step). Says which on standard output.
FbaEncoderOptions fba_choice(const FapSequence& seq, const StreamArgs& a) {
  FbaEncoderOptions o;
  o.fap_quant = 0;  // lossless unless asked or needed otherwise (the options' own default is 1)
  std::string why;
  if (a.profile == "fapcast") {
    o.profile = FbaProfile::kFapcast;
    o.fap_quant = std::max(a.quant, 0);
  } else if (a.quant >= 0 || a.profile == "standard") {
    o.fap_quant = std::max(a.quant, 0);
    if (a.quant < 0)
      while (o.fap_quant < kMaxFapQuant && fba_standard_refusal(seq, o.fap_quant)) ++o.fap_quant;
    if (a.profile != "standard" && fba_standard_refusal(seq, o.fap_quant)) o.profile = FbaProfile::kFapcast;
  } else if (const auto refusal = fba_standard_refusal(seq, 0)) {
    o.profile = FbaProfile::kFapcast;  // auto: lossless, and the standard syntax cannot be
    why = " (the standard syntax cannot code " + *refusal + ")";
  }
  std::cout << "sending:   " << fba_profile_name(o.profile) << " at fap_quant " << o.fap_quant
            << (o.fap_quant == 0 ? ": the values sent, losslessly" : ": every value within half a quantisation step")
            << why << "\n";
  return o;
}

void run_stream(const StreamArgs& a) {
  if (!track_format_of(a.input))
    throw cli::UsageError(a.input + ": expected a .fap, .fba or .json track");
  if (a.payload_type == a.audio_payload_type)
    throw cli::UsageError("--payload-type and --audio-payload-type must differ");
  UdpUrl url;
  if (const auto ec = parse_udp_url(a.to, url)) throw cli::UsageError(a.to + ": " + ec.message());
  boost::system::error_code address_error;
  if (!a.interface.empty()) (void)asio::ip::make_address(a.interface, address_error);
  if (address_error) throw cli::UsageError("--interface " + a.interface + ": not an IP address");
  const FapSequence seq = read_track_file(a.input);
  std::unique_ptr<Audio> audio;
  if (!a.wav.empty()) audio = std::make_unique<Audio>(read_wav(a.wav));

  StreamOptions options;
  options.pace = !a.no_pace;
  options.clock_rate = audio ? audio->sample_rate : kDefaultSampleRate;
  options.animation_payload_type = static_cast<std::uint8_t>(a.payload_type);
  options.audio_payload_type = static_cast<std::uint8_t>(a.audio_payload_type);
  options.rtcp_interval = std::chrono::milliseconds(a.rtcp_ms);
  if (a.ttl >= 0) options.socket.ttl = a.ttl;
  if (!a.interface.empty()) options.socket.interface = asio::ip::make_address(a.interface);
  options.socket.multicast_loopback = !a.no_loopback;
  if (!a.srtp_key_file.empty()) options.srtp = read_srtp_key_file(a.srtp_key_file);

  FbaEncoderOptions fba = fba_choice(seq, a);
  fba.intra_period = a.iperiod;
  std::vector<MediaUnit> units;
  std::int64_t bad_frame = 0;
  if (const auto ec = encode_track_units(seq, options.clock_rate, fba, units, &bad_frame))
    throw std::runtime_error(a.input + ": frame " + std::to_string(bad_frame) + ": " + ec.message());
  // The audio is the timeline: every frame must start within it (a cut-off or wrong WAV).
  if (audio && !units.empty() && audio->instants() <= units.back().sample)
    throw std::runtime_error(a.wav + ": stream-audio-short: " + std::to_string(audio->instants()) +
                             " sampling instants end before the last frame of " + a.input +
                             " starts (sample " + std::to_string(units.back().sample) + ")");

  asio::io_context io;
  const auto destination = resolve_udp_url(io, a.to);
  RtpStreamer streamer(io, destination, options);
  const StreamReport r = streamer.run(units, audio.get());
  std::cout << "animation: " << r.animation.packets << " packets, " << r.animation.payload_octets
            << " payload octets, ssrc " << options.animation_ids.ssrc << ", pt "
            << a.payload_type << ", clock " << options.clock_rate.hz << " Hz\n";
  if (audio)
    std::cout << "audio:     " << r.audio.packets << " packets, " << r.audio.payload_octets
              << " payload octets, ssrc " << options.audio_ids.ssrc << ", pt "
              << a.audio_payload_type << " (L16/" << audio->sample_rate.hz << "/" << audio->channels
              << ")\n";
  std::cout << "rtcp:      " << r.animation.sender_reports + r.audio.sender_reports
            << " sender reports\n";
}

const cli::Registration stream_command{"stream", [](CLI::App& app) {
  auto args = std::make_shared<StreamArgs>();
  auto* cmd = app.add_subcommand("stream", "Send a FAP track (and its audio) as RTP over UDP");
  cmd->add_option("IN", args->input, "Track to send: .fap, .fba or .json")->required();
  cmd->add_option("--wav", args->wav, "Audio to send alongside as L16 (its rate becomes the RTP clock)");
  cmd->add_option("-o,--output", args->to, "Destination udp://HOST:PORT (unicast or a multicast group)")->required();
  cmd->add_flag("--no-pace", args->no_pace, "Send as fast as possible instead of in real time");
  cmd->add_option("--ttl", args->ttl, "Hop limit (multicast TTL)")->check(CLI::Range(0, 255));
  cmd->add_option("--interface", args->interface, "Outgoing interface address for multicast");
  cmd->add_flag("--no-loopback", args->no_loopback, "Do not loop multicast back to this host");
  cmd->add_option("--iperiod", args->iperiod, "An intra frame at least every N frames")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--profile", args->profile,
                  "auto (default: lossless; standard FBA at fap_quant 0 where it codes every value, else the fapcast "
                  "profile), standard (standard FBA only: fap_quant 0 or the smallest that codes every value) or "
                  "fapcast")
      ->check(CLI::IsMember({"auto", "standard", "fapcast"}));
  cmd->add_option("--quant", args->quant, "FBA fap_quant, 0 (lossless) .. 31 (default: see --profile)")
      ->check(CLI::Range(0, 31));
  cmd->add_option("--payload-type", args->payload_type, "RTP payload type of the animation")
      ->check(CLI::Range(96, 127));
  cmd->add_option("--audio-payload-type", args->audio_payload_type, "RTP payload type of the audio")
      ->check(CLI::Range(96, 127));
  cmd->add_option("--rtcp-interval-ms", args->rtcp_ms, "Milliseconds between sender reports (0: none)")
      ->check(CLI::Range(0, 60000));
  cmd->add_option("--srtp-key-file", args->srtp_key_file,
                  "Send SRTP/SRTCP (AES_CM_128_HMAC_SHA1_80) under the base64 master key in this file");
  cmd->callback([args] { run_stream(*args); });
}};

}  // namespace
