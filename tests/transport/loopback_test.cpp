// RTP over real UDP sockets on loopback: exact delivery, recovery from loss, reordering and
// duplication, multicast, audio with sender reports, hostile datagrams, and a tshark capture.
#include "fapcast/transport/l16.hpp"
#include "fapcast/transport/rtcp_compound.hpp"
#include "fapcast/transport/rtcp_sender_report.hpp"
#include "fapcast/transport/rtp_streamer.hpp"
#include "fapcast/transport/udp_receiver.hpp"
#include "support/run_command.hpp"
#include "transport/loopback_support.hpp"
#include "transport/test_seed.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <map>
#include <sstream>

namespace fapcast {
namespace {

using namespace std::chrono_literals;
using test::loopback;
using test::ReceiverThread;

StreamOptions fixed_options(bool pace = true) {
  StreamOptions o;
  o.pace = pace;
  o.animation_ids = {0x5eed0001, 65500, 4'294'960'000u};  // both counters wrap during the test
  o.audio_ids = {0x5eed0002, 100, 7};
  o.rtcp_interval = 0ms;
  return o;
}

TEST(Loopback, DeliversEveryUnitExactlyWithoutLoss) {
  const auto units = test::synthetic_units(300, 25);
  ReceiverThread rx(loopback(), {});
  rx.start(400ms);
  asio::io_context io;
  RtpStreamer streamer(io, rx.receiver.local_endpoint(), fixed_options());
  const StreamReport report = streamer.run(units);
  rx.join();
  EXPECT_EQ(report.animation.packets, 300u);
  ASSERT_EQ(rx.units.size(), units.size()) << rx.stream.stats();
  for (std::size_t i = 0; i < units.size(); ++i) {
    EXPECT_EQ(rx.units[i].bytes, units[i].bytes) << i;
    EXPECT_EQ(rx.units[i].intra, units[i].intra) << i;
    EXPECT_EQ(rx.units[i].timestamp, static_cast<std::uint32_t>(4'294'960'000u + units[i].sample)) << i;
  }
  EXPECT_EQ(rx.stream.stats().lost, 0u);
  EXPECT_EQ(rx.stream.stats().duplicates, 0u);
  EXPECT_EQ(rx.stream.stats().late, 0u);
  EXPECT_EQ(rx.stream.locked_ssrc(), 0x5eed0001u);
}

struct LossCase {
  const char* name;
  double loss;
  double dup;
  double swap;
};
class LossyLoopback : public testing::TestWithParam<LossCase> {};

// What the receiver must deliver, computed independently from what the shim forwarded: from the
// first forwarded sequence number on, every missing one is lost, and after a loss (and at the
// start) only an intra unit resumes delivery.
TEST_P(LossyLoopback, RecoversAtTheNextIntraUnitAndCountsTheLoss) {
  const LossCase& c = GetParam();
  const std::uint64_t seed = test::test_seed(test::kTransportSeed);
  const int n = 400;
  const int iperiod = 10;
  const auto units = test::synthetic_units(n, iperiod);
  ReceiverOptions ro;
  ro.reorder_delay = 60ms;
  ReceiverThread rx(loopback(), ro);
  test::LossyShim shim(rx.receiver.local_endpoint(), c.loss, c.dup, c.swap, seed);
  rx.start(600ms);
  shim.start(300ms);
  asio::io_context io;
  StreamOptions so = fixed_options();
  so.animation_ids.first_sequence = 65400;  // wraps during the run
  RtpStreamer streamer(io, shim.endpoint(), so);
  streamer.run(units);
  shim.join();
  rx.join();

  const auto index_of = [&](std::uint16_t seq) { return static_cast<std::uint16_t>(seq - so.animation_ids.first_sequence); };
  std::set<int> got;
  for (const auto seq : shim.forwarded) got.insert(index_of(seq));
  ASSERT_FALSE(got.empty());
  // The stream starts where the source was validated (two in sequence, RFC 3550 A.1); what was
  // forwarded before that is discarded on probation or late.
  ASSERT_TRUE(rx.stream.first_sequence());
  const int start = index_of(static_cast<std::uint16_t>(*rx.stream.first_sequence()));
  std::uint64_t before_start = 0;
  for (const int i : got) before_start += i < start;
  std::vector<int> expected;
  std::uint64_t expected_lost = 0;
  bool need_intra = true;
  for (int i = start; i <= *got.rbegin(); ++i) {
    if (!got.contains(i)) {
      ++expected_lost;
      need_intra = true;
    } else if (!need_intra || units[static_cast<std::size_t>(i)].intra) {
      need_intra = false;
      expected.push_back(i);
    }
  }
  std::vector<int> delivered;
  for (const auto& u : rx.units) {
    const int i = index_of(static_cast<std::uint16_t>(u.extended_sequence));
    delivered.push_back(i);
    EXPECT_EQ(u.bytes, units[static_cast<std::size_t>(i)].bytes) << i;
    if (u.after_loss) {
      EXPECT_TRUE(u.intra) << "resumed at a predicted unit " << i;
    }
  }
  const ReceiverStats& s = rx.stream.stats();
  EXPECT_EQ(delivered, expected) << s << "\n  reproduce: FAPCAST_SEED=" << seed;
  EXPECT_EQ(s.lost, expected_lost) << s;
  EXPECT_LE(s.duplicates, shim.duplicates_sent) << s;  // a duplicate of a discarded one is late
  EXPECT_LE(s.late, before_start + shim.duplicates_sent) << s;
  EXPECT_GT(shim.dropped, 0u);
  std::cerr << "[loss] " << c.name << ": dropped " << shim.dropped << ", swapped " << shim.swaps
            << ", duplicated " << shim.duplicates_sent << "; receiver: " << s << "\n";
}

INSTANTIATE_TEST_SUITE_P(Table, LossyLoopback,
                         testing::Values(LossCase{"loss10", 0.10, 0.05, 0.10},
                                         LossCase{"loss30", 0.30, 0.10, 0.20}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Loopback, MulticastOnTheLoopbackInterface) {
  const auto group = asio::ip::make_address("239.255.70.7");
  const auto lo = asio::ip::make_address("127.0.0.1");
  std::unique_ptr<ReceiverThread> rx;
  try {
    rx = std::make_unique<ReceiverThread>(udp::endpoint(group, 0), ReceiverOptions{},
                                          ReceiverSocketOptions{std::nullopt, lo});
  } catch (const std::system_error& e) {
    GTEST_SKIP() << "cannot join 239.255.70.7 on 127.0.0.1 in this sandbox: " << e.what();
  }
  rx->start(400ms);
  asio::io_context io;
  StreamOptions so = fixed_options();
  so.socket.ttl = 0;  // never leaves the host
  so.socket.interface = lo;
  so.socket.multicast_loopback = true;
  const auto units = test::synthetic_units(60, 10);
  std::error_code ec;
  RtpStreamer streamer(io, udp::endpoint(group, rx->receiver.local_endpoint().port()), so);
  streamer.run(units, nullptr, ec);
  rx->join();
  if (ec) GTEST_SKIP() << "no multicast route on loopback in this sandbox: " << ec.message();
  ASSERT_EQ(rx->units.size(), units.size()) << rx->stream.stats();
  for (std::size_t i = 0; i < units.size(); ++i) EXPECT_EQ(rx->units[i].bytes, units[i].bytes);
}

// Hostile datagrams from the same and other addresses are interleaved with a real stream: the
// stream still arrives whole and each kind is counted where it belongs.
TEST(Loopback, HostileDatagramsDoNotDisturbTheStream) {
  ReceiverThread rx(loopback(), {});
  rx.start(400ms);
  asio::io_context io;
  UdpSender attacker(io, rx.receiver.local_endpoint());
  std::mt19937_64 rng(test::test_seed(test::kTransportSeed));
  const std::vector<std::vector<std::uint8_t>> hostile{
      {},                                                                  // empty
      {0x80, 96, 0, 1},                                                    // truncated
      {0x40, 96, 0, 1, 0, 0, 0, 0, 0x5e, 0xed, 0, 1, 0x80},                // version 1
      {0x8f, 96, 0, 1, 0, 0, 0, 0, 0x5e, 0xed, 0, 1, 0x80},                // CSRC count lies
      {0x90, 96, 0, 1, 0, 0, 0, 0, 0x5e, 0xed, 0, 1, 0, 0, 0xff, 0xff},    // extension lies
      {0xa0, 96, 0, 1, 0, 0, 0, 0, 0x5e, 0xed, 0, 1, 0x80, 200},           // padding lies
      {0x80, 96, 0, 1, 0, 0, 0, 0, 0x5e, 0xed, 0, 1},                      // no payload header
  };
  const auto units = test::synthetic_units(100, 10);
  StreamOptions so = fixed_options(false);
  std::size_t sent_hostile = 0;
  std::uint64_t foreign = 0;
  std::vector<std::uint8_t> packet;
  udp::socket direct(io, udp::v4());
  for (std::size_t i = 0; i < units.size(); ++i) {
    packet.clear();
    ASSERT_FALSE(pack_animation_packet(units[i], i, so.animation_ids, 96, packet));
    direct.send_to(asio::buffer(packet), rx.receiver.local_endpoint());
    attacker.send(hostile[i % hostile.size()]);
    ++sent_hostile;
    // A well-formed packet of another source, and one with random bytes.
    std::vector<std::uint8_t> other;
    RtpStreamIds ids{0xbad, static_cast<std::uint16_t>(rng()), 0};
    ASSERT_FALSE(pack_animation_packet(units[i], 0, ids, 96, other));
    attacker.send(other);
    ++foreign;
    std::this_thread::sleep_for(200us);  // stay below the socket buffer
  }
  rx.join();
  const ReceiverStats& s = rx.stream.stats();
  EXPECT_EQ(rx.units.size(), units.size()) << s;
  EXPECT_EQ(s.malformed, sent_hostile) << s;
  EXPECT_EQ(s.foreign_ssrc + s.probation_discarded, foreign) << s;  // the first one is on probation
  EXPECT_EQ(s.lost, 0u);
}

TEST(Loopback, SourceFilterRefusesOtherAddresses) {
  ReceiverThread rx(loopback(), {}, ReceiverSocketOptions{asio::ip::make_address("127.0.0.2"), std::nullopt});
  rx.start(300ms);
  asio::io_context io;
  RtpStreamer streamer(io, rx.receiver.local_endpoint(), fixed_options(false));
  streamer.run(test::synthetic_units(20, 5));
  rx.join();
  EXPECT_TRUE(rx.units.empty());
  EXPECT_EQ(rx.filtered, 20u);
}

// Binds four consecutive loopback ports P..P+3 (retrying a few times), for a stream with audio.
std::vector<udp::socket> bind_port_quad(asio::io_context& io) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    std::vector<udp::socket> sockets;
    sockets.emplace_back(io, loopback());
    const auto base = sockets[0].local_endpoint().port();
    if (base > 65532) continue;
    boost::system::error_code ec;
    for (int k = 1; k < 4 && !ec; ++k) {
      udp::socket s(io, udp::v4());
      s.bind(loopback(static_cast<std::uint16_t>(base + k)), ec);
      if (!ec) sockets.push_back(std::move(s));
    }
    if (sockets.size() == 4) return sockets;
  }
  return {};
}

// Collects every datagram on `socket` until idle.
// Only datagrams whose SSRC is one of `ssrcs` are kept: another process on this machine (a
// parallel test run) may still be sending to a port this test has just bound. Sockets 0 and 2
// carry RTP (SSRC at byte 8), 1 and 3 RTCP (SSRC of the first report at byte 4).
std::vector<std::vector<std::uint8_t>> collect(asio::io_context& io, std::vector<udp::socket>& sockets,
                                               std::vector<std::vector<std::vector<std::uint8_t>>>& per_socket,
                                               std::chrono::milliseconds idle,
                                               std::array<std::uint32_t, 2> ssrcs) {
  // One buffer per socket: the reactor reads every ready socket before any handler runs, so
  // with one shared buffer a report arriving with an audio packet overwrote it.
  std::vector<std::array<std::uint8_t, 2048>> buffers(sockets.size());
  auto last = std::chrono::steady_clock::now();
  std::vector<udp::endpoint> from(sockets.size());
  std::vector<bool> pending(sockets.size(), false);
  for (;;) {
    for (std::size_t k = 0; k < sockets.size(); ++k)
      if (!pending[k]) {
        pending[k] = true;
        sockets[k].async_receive_from(asio::buffer(buffers[k]), from[k], [&, k](const boost::system::error_code& ec, std::size_t n) {
          pending[k] = false;
          const auto& buf = buffers[k];
          if (ec) return;
          const std::size_t at = k % 2 == 0 ? 8 : 4;
          if (n < at + 4) return;
          const std::uint32_t ssrc = std::uint32_t{buf[at]} << 24 | std::uint32_t{buf[at + 1]} << 16 |
                                     std::uint32_t{buf[at + 2]} << 8 | buf[at + 3];
          if (ssrc != ssrcs[0] && ssrc != ssrcs[1]) return;
          last = std::chrono::steady_clock::now();
          per_socket[k].emplace_back(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n));
        });
      }
    io.restart();
    io.run_for(5ms);
    if (std::chrono::steady_clock::now() - last > idle) break;
  }
  for (auto& s : sockets) s.cancel();
  io.restart();
  io.run_for(100ms);
  return {};
}

// Audio as L16 at P+2 reassembles the WAV exactly; sender reports at P+1 and P+3 map both
// streams' RTP timestamps to one NTP clock consistently; their counts match what was sent.
TEST(Loopback, AudioAndSenderReportsShareOneClock) {
  asio::io_context rx_io;
  auto sockets = bind_port_quad(rx_io);
  if (sockets.empty()) GTEST_SKIP() << "could not bind four consecutive loopback ports";
  const auto base = sockets[0].local_endpoint();
  Audio audio;
  audio.sample_rate = SampleRate{48000};
  audio.channels = 2;
  for (int i = 0; i < 48000 * 2 / 5; ++i) audio.samples.push_back(static_cast<std::int16_t>(i * 37));  // 0.2 s
  const auto units = test::synthetic_units(12, 6, 800);  // 60 fps over 0.2 s
  std::vector<std::vector<std::vector<std::uint8_t>>> got(4);
  StreamReport report;
  // SSRCs of this process only (see collect).
  const std::uint32_t tag = (static_cast<std::uint32_t>(::getpid()) & 0xffffu) << 8;
  const std::uint32_t animation_ssrc = 0x5e000001u | tag;
  const std::uint32_t audio_ssrc = 0x5e000002u | tag;
  std::thread sender([&] {
    asio::io_context io;
    StreamOptions so = fixed_options();
    so.animation_ids.ssrc = animation_ssrc;
    so.audio_ids.ssrc = audio_ssrc;
    so.rtcp_interval = 50ms;
    RtpStreamer streamer(io, base, so);
    report = streamer.run(units, &audio);
  });
  collect(rx_io, sockets, got, 400ms, {animation_ssrc, audio_ssrc});
  sender.join();
  // Audio: in order on loopback; reassemble and compare.
  std::vector<std::int16_t> samples;
  std::uint32_t expected_ts = 7;
  for (const auto& d : got[2]) {
    RtpPacketView v;
    ASSERT_FALSE(parse_rtp(d, v));
    EXPECT_EQ(v.header.payload_type, 97);
    EXPECT_EQ(v.header.ssrc, audio_ssrc);
    EXPECT_EQ(v.header.timestamp, expected_ts);
    const auto chunk = unpack_l16(v.payload);
    expected_ts += static_cast<std::uint32_t>(chunk.size() / 2);
    samples.insert(samples.end(), chunk.begin(), chunk.end());
  }
  EXPECT_EQ(samples, audio.samples);
  EXPECT_EQ(got[0].size(), units.size());
  // Sender reports: pairs with the same NTP time; media positions agree and follow the NTP clock.
  ASSERT_GE(got[1].size(), 4u);
  ASSERT_EQ(got[1].size(), got[3].size());
  SenderReport first_a;
  ASSERT_FALSE(parse_sender_report(got[1][0], first_a));
  bool closing = false;
  for (std::size_t k = 0; k < got[1].size(); ++k) {
    SenderReport a, b;
    ASSERT_FALSE(parse_sender_report(got[1][k], a));
    ASSERT_FALSE(parse_sender_report(got[3][k], b));
    EXPECT_EQ(a.ssrc, animation_ssrc);
    EXPECT_EQ(b.ssrc, audio_ssrc);
    EXPECT_EQ(a.ntp, b.ntp);
    // Compound packets: SR then SDES with the same CNAME on both streams (the SDES items after
    // its SSRC, up to its length); the last one ends with each stream's own BYE.
    ASSERT_GT(got[1][k].size(), 36u);
    EXPECT_EQ(got[1][k][29], 202);
    const auto sdes_end = [](const std::vector<std::uint8_t>& d) {
      return std::min<std::size_t>(d.size(), 28 + 4 * (((std::size_t{d[30]} << 8) | d[31]) + 1));
    };
    EXPECT_EQ(std::vector<std::uint8_t>(got[1][k].begin() + 36, got[1][k].begin() + sdes_end(got[1][k])),
              std::vector<std::uint8_t>(got[3][k].begin() + 36, got[3][k].begin() + sdes_end(got[3][k])));
    RtcpCompound ca, cb;
    ASSERT_FALSE(parse_rtcp_compound(got[1][k], ca));
    ASSERT_FALSE(parse_rtcp_compound(got[3][k], cb));
    // The closing reports (repeated, against loss) carry each stream's BYE; none before them.
    if (!ca.bye_sources.empty()) closing = true;
    EXPECT_EQ(ca.bye_sources, closing ? std::vector<std::uint32_t>{animation_ssrc} : std::vector<std::uint32_t>{});
    EXPECT_EQ(cb.bye_sources, closing ? std::vector<std::uint32_t>{audio_ssrc} : std::vector<std::uint32_t>{});
    const std::uint32_t pos_a = a.rtp_timestamp - 4'294'960'000u;
    const std::uint32_t pos_b = b.rtp_timestamp - 7u;
    EXPECT_EQ(pos_a, pos_b);  // the same instant on both media clocks
    const auto elapsed = from_ntp(a.ntp) - from_ntp(first_a.ntp);
    EXPECT_NEAR(std::chrono::duration<double>(elapsed).count(), pos_a / 48000.0, 1e-6);
  }
  EXPECT_TRUE(closing) << "no closing report with BYE";
  SenderReport last_a, last_b;
  ASSERT_FALSE(parse_sender_report(got[1].back(), last_a));
  ASSERT_FALSE(parse_sender_report(got[3].back(), last_b));
  EXPECT_EQ(last_a.packet_count, units.size());
  EXPECT_EQ(last_b.packet_count, got[2].size());
  EXPECT_EQ(last_b.octet_count, audio.samples.size() * 2);
  EXPECT_EQ(report.audio.packets, got[2].size());
}

// tshark, capturing on lo with a filter on the chosen port, decodes the stream as RTP with the
// sequence numbers and timestamps we sent.
TEST(Loopback, TsharkDecodesTheStreamAsRtp) {
  if (test::run_command("command -v tshark").exit_code != 0) GTEST_SKIP() << "tshark is not installed";
  asio::io_context io;
  udp::socket sink(io, loopback());
  const auto port = sink.local_endpoint().port();
  const std::string dir = test::make_temp_dir("tshark");
  const std::string pcap = dir + "/rtp.pcap";
  const int n = 20;
  test::CommandResult capture;
  std::thread tshark([&] {
    // The subshell keeps our stderr file: run_command redirects the whole command's stderr.
    capture = test::run_command("(timeout 20 tshark -q -i lo -f 'udp dst port " + std::to_string(port) + "' -c " +
                                std::to_string(n) + " -a duration:15 -w " + pcap + " 2>" + dir + "/err)");
  });
  // Wait (bounded) until tshark says it is capturing.
  for (int i = 0; i < 100; ++i) {
    std::ifstream err(dir + "/err");
    std::stringstream ss;
    ss << err.rdbuf();
    if (ss.str().find("Capturing on") != std::string::npos) break;
    std::this_thread::sleep_for(100ms);
  }
  std::this_thread::sleep_for(200ms);
  StreamOptions so = fixed_options();
  so.animation_ids = {0x7e57, 65530, 4'294'967'000u};
  const auto units = test::synthetic_units(n, 5, 800);
  {
    StreamOptions fast = so;
    fast.pace = false;
    RtpStreamer streamer(io, udp::endpoint(loopback(port)), fast);
    streamer.run(units);
  }
  tshark.join();
  if (capture.exit_code != 0) {
    std::ifstream err(dir + "/err");
    std::stringstream ss;
    ss << err.rdbuf();
    GTEST_SKIP() << "capture on lo not permitted here (exit " << capture.exit_code << "): " << ss.str();
  }
  const auto decoded = test::run_command("tshark -r " + pcap + " -d udp.port==" + std::to_string(port) +
                                         ",rtp -T fields -e rtp.seq -e rtp.timestamp -e rtp.p_type -e rtp.marker");
  ASSERT_EQ(decoded.exit_code, 0) << decoded.err;
  std::ostringstream expected;
  for (int i = 0; i < n; ++i)
    expected << static_cast<std::uint16_t>(65530 + i) << '\t'
             << static_cast<std::uint32_t>(4'294'967'000u + units[static_cast<std::size_t>(i)].sample) << "\t96\t1\n";
  EXPECT_EQ(decoded.out, expected.str());
}

}  // namespace
}  // namespace fapcast
