#include "fapcast/transport/rtp_packet.hpp"

#include "fapcast/transport/fba_payload.hpp"
#include "fapcast/transport/rtp_error.hpp"
#include "transport/test_seed.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fapcast {
namespace {

using Bytes = std::vector<std::uint8_t>;

struct HeaderCase {
  const char* name;
  RtpHeader header;
  std::size_t payload_bytes;
  std::uint8_t padding;
};

RtpHeader with_csrcs(RtpHeader h, int n) {
  h.csrc_count = static_cast<std::uint8_t>(n);
  for (int i = 0; i < n; ++i) h.csrc[static_cast<std::size_t>(i)] = 0x1000u + static_cast<std::uint32_t>(i);
  return h;
}

class RtpHeaderRoundTrip : public testing::TestWithParam<HeaderCase> {};

TEST_P(RtpHeaderRoundTrip, ParsesWhatWasPacked) {
  const HeaderCase& c = GetParam();
  Bytes payload(c.payload_bytes);
  for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<std::uint8_t>(i * 7);
  Bytes packet;
  ASSERT_FALSE(pack_rtp(c.header, payload, packet, c.padding));
  EXPECT_EQ(packet.size(), rtp_header_bytes(c.header) + payload.size() + c.padding);
  RtpPacketView view;
  ASSERT_FALSE(parse_rtp(packet, view));
  RtpHeader expected = c.header;
  expected.padding = c.padding > 0;
  EXPECT_EQ(view.header, expected);
  EXPECT_EQ(Bytes(view.payload.begin(), view.payload.end()), payload);
}

INSTANTIATE_TEST_SUITE_P(
    Table, RtpHeaderRoundTrip,
    testing::Values(
        HeaderCase{"plain", RtpHeader{}, 10, 0},
        HeaderCase{"marker_pt127_wrap", RtpHeader{false, false, true, 127, 65535, 0xffffffffu, 7, 0, {}}, 1, 0},
        HeaderCase{"padding", RtpHeader{false, false, false, 96, 1, 2, 3, 0, {}}, 5, 3},
        HeaderCase{"padding_255_empty", RtpHeader{}, 0, 255},
        HeaderCase{"fifteen_csrcs", with_csrcs(RtpHeader{}, 15), 20, 0},
        HeaderCase{"one_csrc_padding", with_csrcs(RtpHeader{}, 1), 0, 1}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(RtpPacket, WireLayoutMatchesRfc3550) {
  RtpHeader h;
  h.marker = true;
  h.payload_type = 96;
  h.sequence = 0x1234;
  h.timestamp = 0xdeadbeef;
  h.ssrc = 0x01020304;
  const Bytes payload{0xaa};
  Bytes packet;
  ASSERT_FALSE(pack_rtp(h, payload, packet));
  EXPECT_EQ(packet, (Bytes{0x80, 0xe0, 0x12, 0x34, 0xde, 0xad, 0xbe, 0xef, 1, 2, 3, 4, 0xaa}));
}

TEST(RtpPacket, ExtensionIsSkippedAndExposed) {
  // X=1, profile 0xbede, one word of extension, then payload "hi".
  const Bytes packet{0x90, 96, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3, 0xbe, 0xde, 0, 1, 9, 8, 7, 6, 'h', 'i'};
  RtpPacketView view;
  ASSERT_FALSE(parse_rtp(packet, view));
  EXPECT_EQ(view.extension_profile, 0xbede);
  EXPECT_EQ(view.extension_data.size(), 4u);
  EXPECT_EQ(Bytes(view.payload.begin(), view.payload.end()), (Bytes{'h', 'i'}));
}

struct BadCase {
  const char* name;
  Bytes packet;
  RtpErrc error;
};

class RtpHostilePacket : public testing::TestWithParam<BadCase> {};

TEST_P(RtpHostilePacket, IsRefusedWithTheRuleBroken) {
  RtpPacketView view;
  EXPECT_EQ(parse_rtp(GetParam().packet, view), make_error_code(GetParam().error));
}

INSTANTIATE_TEST_SUITE_P(
    Table, RtpHostilePacket,
    testing::Values(
        BadCase{"empty", {}, RtpErrc::kTruncatedHeader},
        BadCase{"eleven_bytes", Bytes(11, 0x80), RtpErrc::kTruncatedHeader},
        BadCase{"version_1", {0x40, 96, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, RtpErrc::kBadVersion},
        BadCase{"version_0", Bytes(12, 0), RtpErrc::kBadVersion},
        BadCase{"csrc_count_lies", {0x8f, 96, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4}, RtpErrc::kCsrcOverrun},
        BadCase{"extension_header_cut", {0x90, 96, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xbe}, RtpErrc::kExtensionOverrun},
        BadCase{"extension_length_lies", {0x90, 96, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xbe, 0xde, 0xff, 0xff, 1, 2, 3, 4}, RtpErrc::kExtensionOverrun},
        BadCase{"padding_zero", {0xa0, 96, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5, 0}, RtpErrc::kBadPadding},
        BadCase{"padding_exceeds_payload", {0xa0, 96, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 3}, RtpErrc::kBadPadding},
        BadCase{"padding_without_payload", {0xa0, 96, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, RtpErrc::kBadPadding}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(RtpPacket, RefusesDatagramsLargerThanOnePacket) {
  Bytes packet;
  EXPECT_EQ(pack_rtp(RtpHeader{}, Bytes(kMaxDatagramBytes), packet), make_error_code(RtpErrc::kPayloadTooLarge));
  EXPECT_TRUE(packet.empty());
}

// Every prefix and every single-byte corruption of a valid packet parses or is refused, and a
// successful parse never points outside the datagram.
TEST(RtpPacket, CorruptionsStayInBounds) {
  const std::uint64_t seed = test::test_seed(test::kTransportSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  RtpHeader h = with_csrcs(RtpHeader{}, 3);
  Bytes packet;
  ASSERT_FALSE(pack_rtp(h, Bytes(40, 0x55), packet, 4));
  for (int trial = 0; trial < 20000; ++trial) {
    Bytes mutated = packet;
    mutated.resize(rng() % (packet.size() + 1));
    if (!mutated.empty()) mutated[rng() % mutated.size()] = static_cast<std::uint8_t>(rng());
    RtpPacketView view;
    if (!parse_rtp(mutated, view)) {
      EXPECT_GE(view.payload.data(), mutated.data());
      EXPECT_LE(view.payload.data() + view.payload.size(), mutated.data() + mutated.size());
    }
  }
}

TEST(FbaPayload, IntraFlagRoundTripsAndEmptyPayloadIsRefused) {
  for (const bool intra : {false, true}) {
    Bytes payload;
    pack_fba_payload(intra, false, Bytes{1, 2, 3}, payload);
    EXPECT_EQ(payload[0], intra ? 0x80 : 0x00);
    FbaPayload parsed;
    ASSERT_FALSE(parse_fba_payload(payload, parsed));
    EXPECT_EQ(parsed.intra, intra);
    EXPECT_FALSE(parsed.fapcast);
    Bytes profiled;
    pack_fba_payload(intra, true, Bytes{1, 2, 3}, profiled);
    EXPECT_EQ(profiled[0], intra ? 0xC0 : 0x40);  // F: the fapcast profile
    ASSERT_FALSE(parse_fba_payload(profiled, parsed));
    EXPECT_TRUE(parsed.fapcast);
    EXPECT_EQ(parsed.intra, intra);
    EXPECT_EQ(Bytes(parsed.access_unit.begin(), parsed.access_unit.end()), (Bytes{1, 2, 3}));
  }
  FbaPayload parsed;
  EXPECT_EQ(parse_fba_payload({}, parsed), make_error_code(RtpErrc::kMissingPayloadHeader));
}

TEST(RtpError, MessagesNameTheRule) {
  EXPECT_EQ(make_error_code(RtpErrc::kBadVersion).message(), "rtp-version: version is not 2");
  EXPECT_STREQ(rtp_category().name(), "fapcast.rtp");
}

}  // namespace
}  // namespace fapcast
