#include "fapcast/transport/l16.hpp"
#include "fapcast/transport/rtcp_sender_report.hpp"
#include "fapcast/transport/rtp_error.hpp"
#include "fapcast/transport/udp_url.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

using Bytes = std::vector<std::uint8_t>;
using std::chrono::system_clock;

TEST(Ntp, UnixEpochAndHalfSecond) {
  EXPECT_EQ(to_ntp(system_clock::time_point{}), (NtpTimestamp{2'208'988'800u, 0}));
  EXPECT_EQ(to_ntp(system_clock::time_point{std::chrono::milliseconds(1500)}),
            (NtpTimestamp{2'208'988'801u, 0x80000000u}));
}

TEST(Ntp, RoundTripsToWithinANanosecond) {
  for (const std::int64_t ns : {0ll, 1ll, 999'999'999ll, 1'763'780'000'123'456'789ll}) {
    const system_clock::time_point t{std::chrono::duration_cast<system_clock::duration>(std::chrono::nanoseconds(ns))};
    const auto back = from_ntp(to_ntp(t));
    EXPECT_LE(std::chrono::abs(back - t), std::chrono::nanoseconds(1)) << ns;
  }
}

TEST(SenderReport, RoundTripAndWireLayout) {
  const SenderReport sr{0x11223344, {0xe0000000u, 0x40000000u}, 123456, 77, 9999};
  Bytes packet;
  pack_sender_report(sr, packet);
  ASSERT_EQ(packet.size(), 28u);
  EXPECT_EQ(packet[0], 0x80);
  EXPECT_EQ(packet[1], 200);
  EXPECT_EQ(packet[3], 6);  // 7 words - 1
  SenderReport parsed;
  ASSERT_FALSE(parse_sender_report(packet, parsed));
  EXPECT_EQ(parsed, sr);
}

TEST(SenderReport, RefusesWhatIsNotOne) {
  Bytes packet;
  pack_sender_report({}, packet);
  SenderReport parsed;
  const auto bad = make_error_code(RtpErrc::kBadRtcp);
  EXPECT_EQ(parse_sender_report(Bytes(packet.begin(), packet.end() - 1), parsed), bad);
  Bytes rr = packet;
  rr[1] = 201;  // receiver report
  EXPECT_EQ(parse_sender_report(rr, parsed), bad);
  Bytes lying = packet;
  lying[0] = 0x81;  // claims a report block it does not have
  EXPECT_EQ(parse_sender_report(lying, parsed), bad);
  Bytes long_length = packet;
  long_length[3] = 200;
  EXPECT_EQ(parse_sender_report(long_length, parsed), bad);
}

TEST(Sdes, CnameChunkIsPaddedToAWordWithANull) {
  Bytes packet;
  pack_sdes_cname(0x01020304, "ab", packet);
  // header (4) + SSRC (4) + type, length, "ab" (4) + null padding to a word (4)
  EXPECT_EQ(packet, (Bytes{0x81, 202, 0, 3, 1, 2, 3, 4, 1, 2, 'a', 'b', 0, 0, 0, 0}));
  for (const std::size_t len : {0u, 1u, 5u, 6u, 255u, 300u}) {
    Bytes p;
    pack_sdes_cname(7, std::string(len, 'x'), p);
    EXPECT_EQ(p.size() % 4, 0u) << len;
    EXPECT_EQ(p.size(), 4u * (((p[2] << 8) | p[3]) + 1u)) << len;  // the length field is right
    EXPECT_EQ(p.back(), 0) << len;                                  // the item list ends with a null
  }
}

TEST(L16, NetworkByteOrderRoundTrip) {
  const std::vector<std::int16_t> samples{0, 1, -1, 32767, -32768, 0x1234};
  Bytes payload;
  pack_l16(samples, payload);
  EXPECT_EQ(payload[10], 0x12);
  EXPECT_EQ(payload[11], 0x34);
  EXPECT_EQ(payload[4], 0xff);
  EXPECT_EQ(unpack_l16(payload), samples);
}

TEST(L16, PacketsFitOneDatagram) {
  for (const int channels : {1, 2, 6, 255})
    for (const std::int64_t rate : {8000, 44100, 48000, 96000, 192000}) {
      const std::size_t n = l16_frames_per_packet(SampleRate{rate}, channels);
      EXPECT_GE(n, 1u);
      EXPECT_LE(n, static_cast<std::size_t>(rate / 100));
      EXPECT_LE(12 + 2 * n * static_cast<std::size_t>(channels), 1452u) << rate << " Hz x" << channels;
    }
  EXPECT_EQ(l16_frames_per_packet(SampleRate{48000}, 1), 480u);  // 10 ms
}

struct UrlCase {
  const char* text;
  bool ok;
  UdpUrl url;
};
class UdpUrlParse : public testing::TestWithParam<UrlCase> {};
TEST_P(UdpUrlParse, SplitsHostAndPort) {
  UdpUrl url;
  const auto ec = parse_udp_url(GetParam().text, url);
  EXPECT_EQ(!ec, GetParam().ok) << GetParam().text;
  if (GetParam().ok) {
    EXPECT_EQ(url, GetParam().url);
  }
}
INSTANTIATE_TEST_SUITE_P(Table, UdpUrlParse,
                         testing::Values(UrlCase{"udp://127.0.0.1:5004", true, {"127.0.0.1", 5004}},
                                         UrlCase{"udp://239.1.2.3:0", true, {"239.1.2.3", 0}},
                                         UrlCase{"udp://[::1]:6000", true, {"::1", 6000}},
                                         UrlCase{"udp://localhost:9", true, {"localhost", 9}},
                                         UrlCase{"tcp://127.0.0.1:5004", false, {}},
                                         UrlCase{"udp://127.0.0.1", false, {}},
                                         UrlCase{"udp://:5004", false, {}},
                                         UrlCase{"udp://127.0.0.1:65536", false, {}},
                                         UrlCase{"udp://127.0.0.1:50x", false, {}},
                                         UrlCase{"udp://::1:5004", false, {}},
                                         UrlCase{"udp://[::1:5004", false, {}}));

TEST(UdpUrl, ResolveNamesTheUrlInErrors) {
  asio::io_context io;
  EXPECT_EQ(resolve_udp_url(io, "udp://127.0.0.1:5004").port(), 5004);
  try {
    resolve_udp_url(io, "udp://nowhere");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("udp://nowhere"), std::string::npos);
  }
}

}  // namespace
}  // namespace fapcast
