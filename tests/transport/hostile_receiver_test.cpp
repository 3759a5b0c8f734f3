// The attacks of issue #17 on the receiver, each as a test: forged and junk packets that would
// take over or silence it, timestamps that would cut or shift the track, a lost first intra
// frame, limits in frames of the stated rate, and 30 % loss with reordering and duplicates,
// through the real sender, real sockets on loopback and the real decoder.
#include "fapcast/core/frame_rate.hpp"
#include "fapcast/transport/fba_payload.hpp"
#include "fapcast/transport/fba_track.hpp"
#include "fapcast/transport/rtcp_compound.hpp"
#include "fapcast/transport/rtp_error.hpp"
#include "fapcast/transport/rtp_streamer.hpp"
#include "fapcast/transport/udp_receiver.hpp"
#include "fapcast/transport/udp_sender.hpp"
#include "transport/loopback_support.hpp"
#include "transport/test_seed.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>

namespace fapcast {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using Clock = RtpStreamReceiver::Clock;

// A SYNTHETIC track in which every frame differs from its neighbours (FAP 3 moves every frame),
// so that a frame one place off its position is seen.
FapSequence moving_track(int n, FrameRate rate) {
  FapSequence seq;
  seq.name = "synthetic";
  seq.rate = rate;
  for (int k = 0; k < n; ++k) {
    FapFrame f;
    f.set(3, static_cast<std::int32_t>(20 * k % 700 - 350));
    f.set(4, static_cast<std::int32_t>(-80 * std::sin(k * 0.07)));
    f.set(12, static_cast<std::int32_t>(40 * std::sin(k * 0.2)));
    seq.frames.push_back(f);
  }
  return seq;
}

// The sender's units and RTP packets of a track (fap_quant 0: decoded frames equal the sent).
struct SentStream {
  FapSequence track;
  std::vector<MediaUnit> units;
  std::vector<Bytes> packets;
  RtpStreamIds ids;
  SentStream(int n, FrameRate rate, int iperiod, RtpStreamIds ids_ = {0x5eed0001, 65500, 4'294'960'000u},
             FbaProfile profile = FbaProfile::kStandard)
      : track(moving_track(n, rate)), ids(ids_) {
    FbaEncoderOptions o;
    o.profile = profile;
    o.fap_quant = 0;
    o.intra_period = iperiod;
    EXPECT_FALSE(encode_track_units(track, SampleRate{48000}, o, units));
    for (std::size_t i = 0; i < units.size(); ++i) {
      Bytes p;
      EXPECT_FALSE(pack_animation_packet(units[i], i, ids, 96, p));
      packets.push_back(std::move(p));
    }
  }
};

ReceiverOptions fba_options() {
  ReceiverOptions o;
  o.make_validator = make_fba_unit_validator;
  return o;
}

// Feeds datagrams 1 ms apart into a receiver and its track.
struct TrackFeed {
  RtpStreamReceiver rx;
  ReceivedTrack track;
  std::vector<ReceivedUnit> out;
  Clock::time_point now = Clock::time_point{} + std::chrono::hours(1);
  explicit TrackFeed(ReceiverOptions o = fba_options(), double max_seconds = 3600)
      : rx(std::move(o)), track(SampleRate{48000}, max_seconds) {}
  std::error_code offer(const Bytes& p) {
    now += 1ms;
    const auto ec = rx.on_datagram(p, now, out);
    drain();
    return ec;
  }
  void drain() {
    for (const auto& u : out) (void)track.add(u);
    out.clear();
  }
  const FapSequence& finish(std::optional<std::uint32_t> sender_packets = std::nullopt) {
    rx.flush(out);
    drain();
    track.finish(sender_packets, rx.anchor_sender_report());
    return track.sequence();
  }
};

Bytes forged(std::uint32_t ssrc, std::uint16_t seq, std::uint32_t timestamp, Bytes payload) {
  RtpHeader h;
  h.marker = true;
  h.payload_type = 96;
  h.sequence = seq;
  h.timestamp = timestamp;
  h.ssrc = ssrc;
  Bytes out;
  EXPECT_FALSE(pack_rtp(h, payload, out));
  return out;
}

// Attack 1: one packet with a parseable header and a 1-byte payload, sent first, used to lock the
// receiver on its SSRC and refuse the real stream. Now it never passes probation.
TEST(HostileReceiver, OneUndecodablePacketCannotTakeTheReceiver) {
  const SentStream s(108, {25, 1}, 10);
  TrackFeed f;
  EXPECT_EQ(f.offer(forged(0xbad, 7, 0, {0x80})), make_error_code(RtpErrc::kUndecodable));
  for (const auto& p : s.packets) EXPECT_FALSE(f.offer(p));
  EXPECT_EQ(f.rx.locked_ssrc(), s.ids.ssrc);
  EXPECT_EQ(f.finish().frames, s.track.frames);
  EXPECT_EQ(f.rx.stats().probation_discarded, 1u) << f.rx.stats();
  EXPECT_EQ(f.rx.stats().foreign_ssrc, 0u);
}

// Attack 1b: a decodable packet of a second source sent before the real stream made the output
// one frame of the intruder's track. One packet is no run: the real stream is validated.
TEST(HostileReceiver, OneDecodablePacketOfAnotherSourceIsNoRun) {
  const SentStream real(108, {25, 1}, 10);
  const SentStream intruder(5, {25, 1}, 1, {0xbad, 1, 0});
  TrackFeed f;
  EXPECT_FALSE(f.offer(intruder.packets[0]));  // decodes: held on probation, not accepted
  for (const auto& p : real.packets) EXPECT_FALSE(f.offer(p));
  EXPECT_EQ(f.rx.locked_ssrc(), real.ids.ssrc);
  EXPECT_EQ(f.finish().frames, real.track.frames);
  EXPECT_EQ(f.rx.stats().probation_discarded, 1u) << f.rx.stats();
}

// A validated source is never displaced: an intruder's decodable run after validation is foreign.
TEST(HostileReceiver, AValidatedSourceIsNeverDisplaced) {
  const SentStream real(60, {25, 1}, 10);
  const SentStream intruder(40, {25, 1}, 1, {0xbad, 1, 0});
  TrackFeed f;
  for (std::size_t i = 0; i < real.packets.size(); ++i) {
    EXPECT_FALSE(f.offer(real.packets[i]));
    if (i >= 10 && i < 50) {
      EXPECT_EQ(f.offer(intruder.packets[i - 10]), make_error_code(RtpErrc::kForeignSsrc));
    }
  }
  EXPECT_EQ(f.finish().frames, real.track.frames);
  EXPECT_EQ(f.rx.stats().foreign_ssrc, 40u);
  EXPECT_EQ(f.rx.stats().validations, 1u);
}

// Only the source's own BYE lets another one in, and only after the reorder delay.
TEST(HostileReceiver, ByeReleasesTheSourceAfterTheReorderDelay) {
  const SentStream first(30, {25, 1}, 10);
  const SentStream second(30, {25, 1}, 10, {0x5ec0, 100, 0});
  TrackFeed f;
  for (const auto& p : first.packets) EXPECT_FALSE(f.offer(p));
  Bytes bye;
  pack_sender_report({0xbad, {}, 0, 1, 1}, bye);
  pack_bye(0xbad, bye);
  EXPECT_EQ(f.rx.on_rtcp(bye, f.now), make_error_code(RtpErrc::kForeignSsrc));  // not ours
  bye.clear();
  pack_sender_report({first.ids.ssrc, {}, 0, 30, 300}, bye);
  pack_sdes_cname(first.ids.ssrc, "fapcast@test", bye);
  pack_bye(first.ids.ssrc, bye);
  EXPECT_FALSE(f.rx.on_rtcp(bye, f.now));
  EXPECT_EQ(f.rx.last_sender_report()->packet_count, 30u);
  EXPECT_FALSE(f.rx.source_left(f.now));
  EXPECT_EQ(f.offer(second.packets[0]), make_error_code(RtpErrc::kForeignSsrc));  // too soon
  f.now += 40ms;
  EXPECT_TRUE(f.rx.source_left(f.now));
  // Its intra unit was refused: its P units cannot start a run, its next intra unit (10) does.
  for (std::size_t i = 1; i < second.packets.size(); ++i) {
    if (i < 10) {
      EXPECT_EQ(f.offer(second.packets[i]), make_error_code(RtpErrc::kUndecodable)) << i;
    } else {
      EXPECT_FALSE(f.offer(second.packets[i])) << i;
    }
  }
  EXPECT_EQ(f.rx.locked_ssrc(), second.ids.ssrc);
  EXPECT_EQ(f.rx.stats().validations, 2u);
  EXPECT_EQ(f.rx.stats().byes, 1u);
  EXPECT_EQ(f.rx.stats().rtcp_refused, 1u);
}

// Probation tolerates reordering: the first packets swapped still start at the first one.
TEST(HostileReceiver, ProbationPutsSwappedFirstPacketsBackInOrder) {
  const SentStream s(50, {60, 1}, 25);
  TrackFeed f;
  EXPECT_EQ(f.offer(s.packets[1]), make_error_code(RtpErrc::kUndecodable));  // P before intra
  for (std::size_t i = 0; i < s.packets.size(); ++i)
    if (i != 1) {
      EXPECT_FALSE(f.offer(s.packets[i]));
    }
  EXPECT_EQ(f.finish().frames, s.track.frames);
  EXPECT_EQ(f.rx.stats().lost, 0u);
}

// Attack 2: one packet in sequence with a timestamp 2^30 ahead cut the track to 51 of 108 frames.
// Unconfirmed by the next packet, it is discarded and counted; the others all land.
TEST(HostileReceiver, OneTimestampJumpDiscardsOneFrameNotTheRest) {
  const SentStream s(108, {25, 1}, 10);
  TrackFeed f;
  for (std::size_t i = 0; i < s.packets.size(); ++i) {
    if (i == 51) {
      Bytes p = s.packets[i];
      const std::uint32_t ts = ((p[4] << 24) | (p[5] << 16) | (p[6] << 8) | p[7]) + (1u << 30);
      p[4] = static_cast<std::uint8_t>(ts >> 24), p[5] = static_cast<std::uint8_t>(ts >> 16);
      p[6] = static_cast<std::uint8_t>(ts >> 8), p[7] = static_cast<std::uint8_t>(ts);
      EXPECT_FALSE(f.offer(p));
      continue;
    }
    EXPECT_FALSE(f.offer(s.packets[i]));
  }
  const auto& got = f.finish(108);
  ASSERT_EQ(got.frames.size(), 108u) << f.rx.stats();
  for (std::size_t k = 0; k < 108; ++k)
    if (k != 51) {
      EXPECT_EQ(got.frames[k], s.track.frames[k]) << k;
    }
  EXPECT_EQ(got.frames[51], got.frames[50]);  // held
  EXPECT_EQ(f.track.stats().timestamp_jumps, 1u);
  EXPECT_EQ(f.track.stats().held_frames, 1u);
}

// A jump that the next packets confirm is the sender's: the frames continue after the last one.
TEST(HostileReceiver, AConfirmedJumpContinuesTheTrack) {
  SentStream s(60, {25, 1}, 1);
  for (std::size_t i = 30; i < s.units.size(); ++i) {
    MediaUnit u = s.units[i];
    u.sample += 48000 * 3600;  // an hour later
    s.packets[i].clear();
    ASSERT_FALSE(pack_animation_packet(u, i, s.ids, 96, s.packets[i]));
  }
  TrackFeed f;
  for (const auto& p : s.packets) EXPECT_FALSE(f.offer(p));
  EXPECT_EQ(f.finish().frames, s.track.frames);
  EXPECT_EQ(f.track.stats().discontinuities, 1u);
  EXPECT_EQ(f.track.stats().timestamp_jumps, 0u);
}

// The sender's 100 frames with the first intra period lost: frames 25.. in place, 0..24 hold 25.
void expect_start_held_from_frame_25(TrackFeed& f, const SentStream& s) {
  const auto& got = f.finish(100);
  ASSERT_EQ(got.frames.size(), 100u);
  for (std::size_t k = 25; k < 100; ++k) EXPECT_EQ(got.frames[k], s.track.frames[k]) << k;
  for (std::size_t k = 0; k < 25; ++k) EXPECT_EQ(got.frames[k], s.track.frames[25]) << k;
  EXPECT_EQ(f.track.stats().leading_frames, 25u);
  EXPECT_EQ(f.track.stats().first_sender_frame, 0);
}

// Attack 5: a lost first intra frame shifted the whole track one intra period early against the
// audio. The fapcast profile's first decoded intra frame carries its frame_number: frame k stays
// frame k.
TEST(HostileReceiver, ALostStartKeepsEveryFrameInItsPlace) {
  const SentStream s(100, {25, 1}, 25, {0x5eed0001, 65500, 4'294'960'000u}, FbaProfile::kFapcast);
  TrackFeed f;
  for (std::size_t i = 3; i < s.packets.size(); ++i) (void)f.offer(s.packets[i]);  // 0..2 lost
  expect_start_held_from_frame_25(f, s);
}

// A standard unit has no frame_number: a sender report made during the stream (packet count 38
// at 1.5 s, the frames that started before it) places the first decoded frame instead.
TEST(HostileReceiver, ALostStandardStartIsPlacedByASenderReport) {
  const SentStream s(100, {25, 1}, 25);
  TrackFeed f;
  for (std::size_t i = 3; i < 40; ++i) (void)f.offer(s.packets[i]);  // 0..2 lost
  Bytes sr;
  pack_sender_report({s.ids.ssrc, {}, s.ids.first_timestamp + 72000, 38, 0}, sr);
  EXPECT_FALSE(f.rx.on_rtcp(sr, f.now));
  for (std::size_t i = 40; i < s.packets.size(); ++i) (void)f.offer(s.packets[i]);
  expect_start_held_from_frame_25(f, s);
}

// Lost last frames are held up to the sender's count from its final sender report.
TEST(HostileReceiver, ALostEndIsHeldUpToTheSendersCount) {
  const SentStream s(100, {25, 1}, 25);
  TrackFeed f;
  for (std::size_t i = 0; i < 93; ++i) EXPECT_FALSE(f.offer(s.packets[i]));
  const auto& got = f.finish(100);
  ASSERT_EQ(got.frames.size(), 100u);
  for (std::size_t k = 93; k < 100; ++k) EXPECT_EQ(got.frames[k], s.track.frames[92]);
  EXPECT_EQ(f.track.stats().trailing_frames, 7u);
}

// Attack 4: --max-seconds was applied as seconds x 120 frames. The limit is frames of the
// stream's own rate: 2 s at 25 fps are 50 frames, and hostile timestamps cannot grow the track.
TEST(HostileReceiver, MaxSecondsIsFramesOfTheStatedRate) {
  const SentStream s(200, {25, 1}, 1);
  TrackFeed f(fba_options(), 2.0);
  for (std::size_t i = 0; i < s.packets.size(); ++i) {
    Bytes p = s.packets[i];
    if (i > 0 && i % 2 == 0) {  // every other timestamp 9 s ahead of the last: hold 225 frames
      MediaUnit u = s.units[i];
      u.sample = s.units[i - 1].sample + 9 * 48000;
      p.clear();
      ASSERT_FALSE(pack_animation_packet(u, i, s.ids, 96, p));
    }
    (void)f.offer(p);
  }
  EXPECT_EQ(f.finish(200).frames.size(), 50u);
  EXPECT_TRUE(f.track.full());
  EXPECT_EQ(f.track.max_frames(), 50);
  EXPECT_GT(f.track.stats().over_limit, 0u);
}

// Junk flood from many SSRCs: probation state stays bounded and the stream still validates.
TEST(HostileReceiver, AFloodOfSourcesStaysBounded) {
  const SentStream s(100, {25, 1}, 10);
  TrackFeed f;
  std::mt19937_64 rng(test::test_seed(test::kTransportSeed));
  for (std::size_t i = 0; i < s.packets.size(); ++i) {
    for (int j = 0; j < 20; ++j) {
      Bytes junk(1 + rng() % 40);
      for (auto& b : junk) b = static_cast<std::uint8_t>(rng());
      junk[0] = rng() % 2 ? kFbaIntraFlag : 0;
      (void)f.offer(forged(static_cast<std::uint32_t>(rng()), static_cast<std::uint16_t>(rng()),
                           static_cast<std::uint32_t>(rng()), junk));
    }
    (void)f.offer(s.packets[i]);
  }
  EXPECT_EQ(f.rx.locked_ssrc(), s.ids.ssrc);
  EXPECT_EQ(f.finish().frames, s.track.frames);
}

// ---- Real sockets on loopback.

// Attack 3: any datagram reset the idle timer, so one junk datagram per 50 ms kept the receiver
// from ever finishing. Only accepted packets feed it now.
TEST(HostileLoopback, JunkDoesNotKeepTheReceiverWaiting) {
  ReceiverOptions o = fba_options();
  test::ReceiverThread rx(test::loopback(), o);
  const auto start = std::chrono::steady_clock::now();
  rx.start(300ms);
  asio::io_context io;
  UdpSender junk(io, rx.receiver.local_endpoint());
  for (int i = 0; i < 40; ++i) {  // 2 s of junk at 20 datagrams/s
    junk.send(forged(0xbad, static_cast<std::uint16_t>(i), 0, {0x80, 1, 2}));
    junk.send(Bytes{1, 2, 3});
    // A unit that decodes, each from a new source: held on probation, never a run, never accepted.
    junk.send(SentStream(1, {25, 1}, 1, {0x1000u + static_cast<std::uint32_t>(i), 7, 0}).packets[0]);
    std::this_thread::sleep_for(50ms);
    if (std::chrono::steady_clock::now() - start > 1s) break;
  }
  rx.join();
  // It ended while the junk still came (idle 300 ms after the start), not 300 ms after the junk.
  EXPECT_EQ(rx.report.end, ReceiveEnd::kIdle);
  EXPECT_LT(rx.ended - start, 800ms);
  EXPECT_GT(rx.stream.stats().malformed + rx.stream.stats().probation_discarded, 0u);
}

// Forwards RTP (port P) and RTCP (P+1) to a receiver with the same seeded loss, duplication and
// swaps: two LossyShims bound to a port pair.
struct LossyPair {
  std::unique_ptr<test::LossyShim> rtp, rtcp;
  LossyPair(udp::endpoint to, double loss, double dup, double swap, std::uint64_t seed,
            int drop_first) {
    for (int attempt = 0; attempt < 32 && !rtcp; ++attempt) {
      rtp = std::make_unique<test::LossyShim>(to, loss, dup, swap, seed, 0, drop_first);
      try {
        rtcp = std::make_unique<test::LossyShim>(
            udp::endpoint(to.address(), static_cast<std::uint16_t>(to.port() + 1)), loss, dup, swap,
            seed + 1, static_cast<std::uint16_t>(rtp->endpoint().port() + 1));
      } catch (const std::exception&) {
        rtcp.reset();
      }
    }
  }
};

struct LossRun {
  const char* name;
  FrameRate rate;
  int frames;
  int drop_first;  // the first RTP datagrams are dropped outright (a lost first intra frame)
};
class ThirtyPercentLoss : public testing::TestWithParam<LossRun> {};

// spec/rtp.md, "Under loss": the real sender (paced, sender reports, BYE) through 30 % loss,
// 10 % duplicates and 20 % swaps on RTP and RTCP alike, into the receiver, the validation and the
// track: frames out = frames sent, and every decoded frame sits exactly where the sender put it
// (audio offset 0 frames; held frames repeat the one before).
TEST_P(ThirtyPercentLoss, FramesOutEqualFramesSentAndStayInSync) {
  const LossRun& c = GetParam();
  const std::uint64_t seed = test::test_seed(test::kTransportSeed) + static_cast<std::uint64_t>(c.frames);
  const FapSequence sent = moving_track(c.frames, c.rate);
  FbaEncoderOptions eo;
  eo.fap_quant = 0;
  eo.intra_period = 25;
  std::vector<MediaUnit> units;
  ASSERT_FALSE(encode_track_units(sent, SampleRate{48000}, eo, units));

  ReceiverOptions ro = fba_options();
  ro.reorder_delay = 60ms;
  asio::io_context rx_io;
  UdpReceiver receiver(rx_io, test::loopback());
  RtpStreamReceiver stream(ro);
  ReceivedTrack got(SampleRate{48000}, 3600);
  LossyPair shim(receiver.local_endpoint(), 0.30, 0.10, 0.20, seed, c.drop_first);
  ASSERT_TRUE(shim.rtcp) << "no free port pair for the shim";
  ReceiveReport report;
  std::thread rx([&] {
    ReceiveLimits limits;
    // recv's default: only accepted packets feed it, and with the start lost no packet is accepted
    // before the next intra unit validates the source (1 s or 2 s into the stream, loss permitting).
    limits.idle_timeout = 5s;
    limits.max_duration = 20s;
    report = receiver.run(stream, limits, [&](ReceivedUnit&& u) { (void)got.add(u); });
  });
  shim.rtp->start(1500ms);
  shim.rtcp->start(1500ms);
  asio::io_context io;
  StreamOptions so;
  so.pace = true;
  so.animation_ids = {0x5eed0001, 65500, 4'294'960'000u};
  so.rtcp_interval = 200ms;
  RtpStreamer streamer(io, shim.rtp->endpoint(), so);
  streamer.run(units);
  rx.join();
  shim.rtp->join();
  shim.rtcp->join();
  const auto& last = stream.last_sender_report();
  got.finish(last ? std::optional<std::uint32_t>(last->packet_count) : std::nullopt,
             stream.anchor_sender_report());
  const FapSequence& out = got.sequence();
  const ReceiverStats& s = stream.stats();
  std::cerr << "[loss30] " << c.name << ": sent " << units.size() << " frames, dropped "
            << shim.rtp->dropped << " RTP + " << shim.rtcp->dropped << " RTCP, swapped "
            << shim.rtp->swaps << ", duplicated " << shim.rtp->duplicates_sent << "; out "
            << out.frames.size() << " frames (" << got.stats().decoded << " decoded, "
            << got.stats().leading_frames << " leading, " << got.stats().held_frames << " held, "
            << got.stats().trailing_frames << " trailing); end: " << to_string(report.end)
            << "; " << s << "\n";
  EXPECT_EQ(report.end, ReceiveEnd::kBye);
  ASSERT_EQ(out.frames.size(), sent.frames.size()) << "reproduce: FAPCAST_SEED=" << seed;
  std::size_t exact = 0;
  std::int64_t worst_offset = 0;
  for (std::size_t k = 0; k < out.frames.size(); ++k) {
    if (out.frames[k] == sent.frames[k]) {
      ++exact;
      continue;
    }
    // Not the sender's frame k: it must hold a frame the sender showed earlier (a gap), never a
    // later one (a shift); the offset is how far back.
    std::int64_t j = static_cast<std::int64_t>(k) - 1;
    while (j >= 0 && out.frames[k] != sent.frames[static_cast<std::size_t>(j)]) --j;
    if (j < 0) {  // a lost start holds the first decoded frame
      ASSERT_LT(k, got.stats().leading_frames) << "frame " << k << " matches no earlier sent frame";
      continue;
    }
    worst_offset = std::max<std::int64_t>(worst_offset, static_cast<std::int64_t>(k) - j);
  }
  EXPECT_EQ(exact, got.stats().decoded) << "every decoded frame at its own place";
  EXPECT_GT(s.lost, 0u);
  EXPECT_GT(s.duplicates, 0u);
  std::cerr << "[loss30] " << c.name << ": " << exact << " frames exact, held frames repeat up to "
            << worst_offset << " frames back\n";
}

INSTANTIATE_TEST_SUITE_P(Table, ThirtyPercentLoss,
                         testing::Values(LossRun{"fps25", {25, 1}, 100, 0},
                                         LossRun{"fps60", {60, 1}, 150, 0},
                                         LossRun{"fps30000_1001", {30000, 1001}, 90, 0},
                                         LossRun{"fps25_lost_start", {25, 1}, 75, 3}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace fapcast
