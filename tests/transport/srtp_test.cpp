// SRTP (libsrtp2): the key's text form and its named bad inputs, protect/unprotect of RTP and
// RTCP, and on loopback sockets: an SRTP stream arrives whole; packets under another key, plain
// RTP, tampered and replayed packets are refused and counted and never reach the stream.
#include "fapcast/core/input_error.hpp"
#include "fapcast/transport/l16.hpp"
#include "fapcast/transport/rtcp_compound.hpp"
#include "fapcast/transport/rtcp_sender_report.hpp"
#include "fapcast/transport/rtp_streamer.hpp"
#include "fapcast/transport/srtp_error.hpp"
#include "fapcast/transport/srtp_session.hpp"
#include "fapcast/transport/udp_receiver.hpp"
#include "support/bad_inputs.hpp"
#include "support/run_command.hpp"
#include "transport/loopback_support.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

namespace fapcast {
namespace {

using namespace std::chrono_literals;
using test::loopback;
using test::ReceiverThread;

// 30 bytes 0x00..0x1d.
SrtpMasterKey counting_key(std::uint8_t start = 0) {
  SrtpMasterKey k;
  for (std::size_t i = 0; i < k.bytes.size(); ++i) k.bytes[i] = static_cast<std::uint8_t>(start + i);
  return k;
}

std::string key_error(std::string_view text) {
  try {
    (void)parse_srtp_key(text, "key");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(SrtpKey, Base64RoundTripsAndAcceptsSdpInlineForm) {
  const SrtpMasterKey k = counting_key();
  const std::string text = srtp_key_text(k);
  EXPECT_EQ(text, "AAECAwQFBgcICQoLDA0ODxAREhMUFRYXGBkaGxwd");  // RFC 4648 base64 of 0x00..0x1d
  EXPECT_EQ(parse_srtp_key(text, "k"), k);
  EXPECT_EQ(parse_srtp_key(" inline:" + text + "\t", "k"), k);
  const SrtpMasterKey r = random_srtp_key();
  EXPECT_EQ(parse_srtp_key(srtp_key_text(r), "k"), r);
}

TEST(SrtpKey, NamedBadKeysAndTheirMessages) {
  EXPECT_EQ(key_error("AAECAwQFBgcICQoLDA0ODxAREhMUFRYXGBkaGx!d"),
            "key: byte 38: srtp-key-base64: character 33 is not base64 (A-Z a-z 0-9 + /)");
  EXPECT_EQ(key_error("AAECAwQFBgcICQoLDA0ODxAREhMUFRYXGBkaGxwdHh8g"),
            "key: byte 0: srtp-key-length: 33 bytes; AES_CM_128_HMAC_SHA1_80 takes 30 (16 of key, 14 of salt: 40 base64 characters)");
  EXPECT_EQ(key_error("AAECAwQFBgcICQoLDA0ODxAREhMUFRYXGBkaGxw"),
            "key: byte 39: srtp-key-base64: 39 characters: base64 comes in groups of 4");
  EXPECT_EQ(key_error("AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA"),
            "key: byte 0: srtp-key-weak: every byte is the same: a placeholder, not a key");
  EXPECT_EQ(key_error("AA==AwQFBgcICQoLDA0ODxAREhMUFRYXGBkaGxwd"),
            "key: byte 4: srtp-key-base64: data after '=' padding");
  EXPECT_EQ(key_error(""), "key: byte 0: srtp-key-length: 0 bytes; AES_CM_128_HMAC_SHA1_80 takes 30 (16 of key, 14 of salt: 40 base64 characters)");
}

// The named bad key files (tests/data/srtp/bad/bad.NNN.<rule>.key) against their golden messages.
const std::filesystem::path kBadKeys = std::filesystem::path(FAPCAST_TEST_DATA) / "srtp" / "bad";

TEST(SrtpKey, NamedBadKeyFilesGiveTheirGoldenMessages) {
  const auto golden = test::golden_errors(kBadKeys);
  const auto names = test::bad_input_names(kBadKeys, ".key");
  EXPECT_EQ(names.size(), 8u);
  for (const std::string& name : names) {
    std::string message = "accepted";
    try {
      (void)read_srtp_key_file(kBadKeys / name);
    } catch (const InputError& e) {
      message = e.what();
      EXPECT_EQ(e.rule(), test::rule_of(name)) << name;
    }
    const std::string prefix = (kBadKeys / "").string();
    if (message.starts_with(prefix)) message.erase(0, prefix.size());
    ASSERT_TRUE(golden.count(name)) << name << " has no line in expected-errors.txt; it says: " << message;
    EXPECT_EQ(message, golden.at(name));
  }
  EXPECT_EQ(golden.size(), names.size()) << "a line of expected-errors.txt names no file";
}

TEST(SrtpKey, AKeyFileReadsWithOrWithoutItsNewline) {
  const std::string dir = test::make_temp_dir("srtp-key");
  std::ofstream(dir + "/crlf.key") << "inline:" << srtp_key_text(counting_key()) << "\r\n";
  std::ofstream(dir + "/bare.key") << srtp_key_text(counting_key(5));
  EXPECT_EQ(read_srtp_key_file(dir + "/crlf.key"), counting_key());
  EXPECT_EQ(read_srtp_key_file(dir + "/bare.key"), counting_key(5));
  EXPECT_THROW((void)read_srtp_key_file(dir + "/missing.key"), std::runtime_error);
}

std::vector<std::uint8_t> rtp_packet(std::uint16_t seq, std::uint32_t ssrc = 0x1234) {
  RtpHeader h;
  h.sequence = seq;
  h.timestamp = 1000u * seq;
  h.ssrc = ssrc;
  h.marker = true;
  const std::vector<std::uint8_t> payload = {0x80, 1, 2, 3, 4, 5, static_cast<std::uint8_t>(seq)};
  std::vector<std::uint8_t> out;
  EXPECT_FALSE(pack_rtp(h, payload, out));
  return out;
}

TEST(SrtpSession, ProtectsAndUnprotectsRtpAndRtcp) {
  SrtpSession tx(counting_key(), SrtpDirection::kSend), rx(counting_key(), SrtpDirection::kReceive);
  for (std::uint16_t seq = 65530; seq != 5; ++seq) {  // across the sequence wrap (the ROC)
    const auto plain = rtp_packet(seq);
    auto wire = plain;
    ASSERT_FALSE(tx.protect_rtp(wire));
    ASSERT_EQ(wire.size(), plain.size() + kSrtpRtpOverheadBytes);
    EXPECT_TRUE(std::equal(plain.begin(), plain.begin() + 12, wire.begin())) << "the header stays clear";
    EXPECT_NE(std::vector(wire.begin() + 12, wire.begin() + static_cast<long>(plain.size())),
              std::vector(plain.begin() + 12, plain.end()))
        << "the payload is encrypted";
    std::size_t n = 0;
    ASSERT_FALSE(rx.unprotect_rtp(wire, n)) << seq;
    wire.resize(n);
    EXPECT_EQ(wire, plain);
  }
  std::vector<std::uint8_t> sr;
  pack_sender_report({0x1234, {3976214400u, 1u << 31}, 42, 7, 99}, sr);
  const auto plain_sr = sr;
  ASSERT_FALSE(tx.protect_rtcp(sr));
  EXPECT_EQ(sr.size(), plain_sr.size() + kSrtcpOverheadBytes);
  std::size_t n = 0;
  ASSERT_FALSE(rx.unprotect_rtcp(sr, n));
  sr.resize(n);
  SenderReport parsed;
  ASSERT_FALSE(parse_sender_report(sr, parsed));
  EXPECT_EQ(parsed.rtp_timestamp, 42u);
  EXPECT_EQ(rx.stats().unprotected_packets, 12u);
  EXPECT_EQ(tx.stats().protected_packets, 12u);
}

TEST(SrtpSession, RefusesOtherKeysTamperingReplaysAndPlainRtp) {
  SrtpSession tx(counting_key(), SrtpDirection::kSend), rx(counting_key(), SrtpDirection::kReceive);
  SrtpSession stranger(counting_key(7), SrtpDirection::kSend);
  std::size_t n = 0;
  auto good = rtp_packet(10);
  ASSERT_FALSE(tx.protect_rtp(good));
  auto copy = good;
  ASSERT_FALSE(rx.unprotect_rtp(copy, n));
  copy = good;
  EXPECT_EQ(rx.unprotect_rtp(copy, n), SrtpErrc::kReplayed);  // the same packet again

  auto foreign = rtp_packet(11);  // another key, same SSRC
  ASSERT_FALSE(stranger.protect_rtp(foreign));
  EXPECT_EQ(rx.unprotect_rtp(foreign, n), SrtpErrc::kAuthFailed);

  auto tampered = rtp_packet(12);
  ASSERT_FALSE(tx.protect_rtp(tampered));
  tampered[14] ^= 1;
  EXPECT_EQ(rx.unprotect_rtp(tampered, n), SrtpErrc::kAuthFailed);

  auto plain = rtp_packet(13);  // unprotected RTP: its last 10 bytes are no tag
  plain.resize(plain.size() + kSrtpRtpOverheadBytes, 0);
  EXPECT_EQ(rx.unprotect_rtp(plain, n), SrtpErrc::kAuthFailed);

  std::vector<std::uint8_t> tiny = {0x80, 0x60, 0, 1};
  EXPECT_EQ(rx.unprotect_rtp(tiny, n), SrtpErrc::kMalformed);

  auto after = rtp_packet(14);  // the stream goes on after the refusals
  ASSERT_FALSE(tx.protect_rtp(after));
  EXPECT_FALSE(rx.unprotect_rtp(after, n));
  EXPECT_EQ(rx.stats().unprotected_packets, 2u);
  EXPECT_EQ(rx.stats().replayed, 1u);
  EXPECT_EQ(rx.stats().auth_failed, 3u);
  EXPECT_EQ(rx.stats().malformed, 1u);
}

TEST(SrtpSession, RefusesAPacketThatWouldNotFitOneDatagram) {
  SrtpSession tx(counting_key(), SrtpDirection::kSend);
  RtpHeader h;
  std::vector<std::uint8_t> big;
  ASSERT_FALSE(pack_rtp(h, std::vector<std::uint8_t>(kMaxDatagramBytes - 12 - 5, 1), big));
  EXPECT_EQ(tx.protect_rtp(big), SrtpErrc::kTooLarge);
}

// L16 packets leave room for the tag: 48 kHz stereo fits 360 instants in the clear, 357 with
// SRTP's 10 bytes, and the protected packet still fits one datagram.
TEST(SrtpSession, L16PacketsWithTheTagStillFitOneDatagram) {
  EXPECT_EQ(l16_frames_per_packet(SampleRate{48000}, 2), 360u);
  EXPECT_EQ(l16_frames_per_packet(SampleRate{48000}, 2, kSrtpRtpOverheadBytes), 357u);
  SrtpSession tx(counting_key(), SrtpDirection::kSend);
  for (const int channels : {1, 2, 6}) {
    const std::size_t n = l16_frames_per_packet(SampleRate{96000}, channels, kSrtpRtpOverheadBytes);
    std::vector<std::uint8_t> payload;
    pack_l16(std::vector<std::int16_t>(n * static_cast<std::size_t>(channels), 7), payload);
    RtpHeader h;
    h.sequence = static_cast<std::uint16_t>(channels);  // one session never protects an index twice
    std::vector<std::uint8_t> packet;
    ASSERT_FALSE(pack_rtp(h, payload, packet));
    ASSERT_FALSE(tx.protect_rtp(packet)) << channels;
    EXPECT_LE(packet.size(), kMaxDatagramBytes) << channels;
  }
}

ReceiverSocketOptions srtp_sockets(const SrtpMasterKey& key) {
  ReceiverSocketOptions o;
  o.srtp = key;
  return o;
}

StreamOptions srtp_stream(const SrtpMasterKey& key) {
  StreamOptions o;
  o.pace = false;
  o.rtcp_interval = 0ms;
  o.srtp = key;
  return o;
}

TEST(SrtpLoopback, AnSrtpStreamArrivesWholeUnderItsKey) {
  const auto units = test::synthetic_units(200, 25);
  ReceiverThread rx(loopback(), {}, srtp_sockets(counting_key()));
  rx.start(300ms);
  asio::io_context io;
  RtpStreamer(io, rx.receiver.local_endpoint(), srtp_stream(counting_key())).run(units);
  rx.join();
  ASSERT_EQ(rx.units.size(), units.size()) << rx.stream.stats();
  for (std::size_t i = 0; i < units.size(); ++i) EXPECT_EQ(rx.units[i].bytes, units[i].bytes) << i;
  ASSERT_NE(rx.receiver.srtp_stats(), nullptr);
  EXPECT_EQ(rx.receiver.srtp_stats()->unprotected_packets, units.size());
  EXPECT_EQ(rx.receiver.srtp_stats()->auth_failed, 0u);
}

TEST(SrtpLoopback, AnotherKeyAndPlainRtpDeliverNothingAndAreCounted) {
  const auto units = test::synthetic_units(50, 25);
  ReceiverThread rx(loopback(), {}, srtp_sockets(counting_key()));
  rx.start(300ms);
  asio::io_context io;
  RtpStreamer(io, rx.receiver.local_endpoint(), srtp_stream(counting_key(9))).run(units);
  StreamOptions plain = srtp_stream(counting_key());
  plain.srtp.reset();
  RtpStreamer(io, rx.receiver.local_endpoint(), plain).run(units);
  rx.join();
  EXPECT_TRUE(rx.units.empty());
  EXPECT_EQ(rx.stream.stats().datagrams, 0u) << "nothing unauthenticated reaches the RTP parser";
  const SrtpStats& s = *rx.receiver.srtp_stats();
  EXPECT_EQ(s.auth_failed + s.malformed, 2 * units.size());
}

TEST(SrtpLoopback, ReplayedDatagramsAreRefusedAndCounted) {
  const auto units = test::synthetic_units(120, 25);
  ReceiverThread rx(loopback(), {}, srtp_sockets(counting_key()));
  rx.start(400ms);
  test::LossyShim shim(rx.receiver.local_endpoint(), 0.0, 1.0, 0.0, 1);  // every datagram twice
  shim.start(300ms);
  asio::io_context io;
  RtpStreamer(io, shim.endpoint(), srtp_stream(counting_key())).run(units);
  shim.join();
  rx.join();
  EXPECT_EQ(rx.units.size(), units.size());
  EXPECT_EQ(rx.receiver.srtp_stats()->replayed, shim.duplicates_sent);
  EXPECT_EQ(rx.stream.stats().duplicates, 0u) << "SRTP refused the copies before the RTP layer saw them";
}

// SRTCP goes through the same session before the RTCP parser: the sender's closing reports
// authenticate, their BYE ends the session at once (not at the idle timeout), and the sender
// reports are counted as #17's receiver counts them.
TEST(SrtpLoopback, SrtcpReportsAndByeAuthenticateAndEndTheSession) {
  const auto units = test::synthetic_units(60, 25);
  ReceiverThread rx(loopback(), {}, srtp_sockets(counting_key()));
  rx.start(3000ms);
  asio::io_context io;
  StreamOptions o = srtp_stream(counting_key());
  o.rtcp_interval = 1000ms;
  const auto sent = std::chrono::steady_clock::now();
  RtpStreamer(io, rx.receiver.local_endpoint(), o).run(units);
  rx.join();
  EXPECT_EQ(rx.units.size(), units.size());
  EXPECT_EQ(rx.report.end, ReceiveEnd::kBye);
  EXPECT_LT(rx.ended - sent, 2000ms) << "the BYE, not the idle timer, ended it";
  EXPECT_GE(rx.stream.stats().byes, 1u);
  EXPECT_GE(rx.stream.stats().sender_reports, 1u);
  EXPECT_EQ(rx.stream.stats().rtcp_refused, 0u);
  EXPECT_EQ(rx.receiver.srtp_stats()->auth_failed + rx.receiver.srtp_stats()->malformed, 0u);
}

// A spoofed BYE (plain RTCP from the source's own address, naming its SSRC) cannot end an SRTP
// session: it is refused before the RTCP parser and counted, and the session runs to its idle
// timeout.
TEST(SrtpLoopback, ASpoofedPlainByeIsRefusedAndCounted) {
  const auto units = test::synthetic_units(40, 25);
  ReceiverThread rx(loopback(), {}, srtp_sockets(counting_key()));
  rx.start(300ms);
  asio::io_context io;
  StreamOptions o = srtp_stream(counting_key());  // no RTCP of its own
  o.animation_ids.ssrc = 0xfeed0001;
  RtpStreamer(io, rx.receiver.local_endpoint(), o).run(units);
  std::vector<std::uint8_t> bye;
  pack_sender_report({o.animation_ids.ssrc, {3976214400u, 0}, 0, 40, 40}, bye);
  pack_bye(o.animation_ids.ssrc, bye);
  udp::socket spoofer(io, udp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
  const udp::endpoint rtcp_port(rx.receiver.local_endpoint().address(),
                                static_cast<std::uint16_t>(rx.receiver.local_endpoint().port() + 1));
  std::this_thread::sleep_for(50ms);  // the receiver validates the source first (else RTCP is filtered)
  for (int i = 0; i < 3; ++i) spoofer.send_to(asio::buffer(bye), rtcp_port);
  rx.join();
  EXPECT_EQ(rx.units.size(), units.size());
  EXPECT_EQ(rx.report.end, ReceiveEnd::kIdle);
  EXPECT_EQ(rx.stream.stats().byes, 0u);
  EXPECT_EQ(rx.report.rtcp_datagrams, 3u);
  const SrtpStats& s = *rx.receiver.srtp_stats();
  EXPECT_EQ(s.auth_failed + s.malformed + rx.report.rtcp_filtered, 3u);  // plain RTCP is malformed SRTCP
  EXPECT_GE(s.auth_failed + s.malformed, 1u);
  EXPECT_EQ(s.replayed, 0u);
}

}  // namespace
}  // namespace fapcast
