// libFuzzer target for the RTP packet parser, the RTCP sender-report parser and the receiver
// state machine. Input layout: a sequence of records [len_hi len_lo dt_ms bytes...]: each
// record is one datagram of `len` bytes (clamped to what is left) arriving dt_ms after the
// previous one; a record whose dt_ms has its top bit set is RTCP. Every datagram goes through
// parse_rtp and parse_rtcp_compound; all go through one RtpStreamReceiver with the FBA source
// validation, whose buffer must stay within its capacity, and the delivered units through a
// ReceivedTrack (FBA decoding, timestamp placement) with a small limit that must hold.
#include "fapcast/transport/fba_track.hpp"
#include "fapcast/transport/rtcp_compound.hpp"
#include "fapcast/transport/rtp_packet.hpp"
#include "fapcast/transport/rtp_stream_receiver.hpp"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  ReceiverOptions options;
  options.reorder_capacity = 8;
  options.make_validator = make_fba_unit_validator;
  RtpStreamReceiver receiver(options);
  ReceivedTrack track(SampleRate{48000}, 4.0);
  std::vector<ReceivedUnit> units;
  RtpStreamReceiver::Clock::time_point now{};
  std::size_t at = 0;
  while (at + 3 <= size) {
    const std::size_t len = std::min<std::size_t>((std::size_t{data[at]} << 8) | data[at + 1], size - at - 3);
    const bool rtcp = (data[at + 2] & 0x80) != 0;
    now += std::chrono::milliseconds(data[at + 2] & 0x7f);
    const std::span<const std::uint8_t> datagram(data + at + 3, len);
    at += 3 + len;
    RtpPacketView view;
    if (!parse_rtp(datagram, view)) {
      if (view.payload.data() < datagram.data() ||
          view.payload.data() + view.payload.size() > datagram.data() + datagram.size())
        std::abort();
    }
    RtcpCompound compound;
    (void)parse_rtcp_compound(datagram, compound);
    if (rtcp)
      (void)receiver.on_rtcp(datagram, now);
    else
      (void)receiver.on_datagram(datagram, now, units);
    receiver.poll(now, units);
    if (receiver.held_packets() > options.reorder_capacity) std::abort();
    for (const auto& u : units) (void)track.add(u);
    units.clear();
  }
  receiver.flush(units);
  for (const auto& u : units) (void)track.add(u);
  const auto& sr = receiver.last_sender_report();
  // As recv does: the report made during the stream places a lost start (hostile reports reach it).
  track.finish(sr ? std::optional<std::uint32_t>(sr->packet_count) : std::nullopt, receiver.anchor_sender_report());
  if (static_cast<std::int64_t>(track.sequence().frames.size()) > track.max_frames()) std::abort();
  return 0;
}
