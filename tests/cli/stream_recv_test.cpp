// `fapcast stream` into `fapcast recv` on loopback, end to end through the executable.
#include "fapcast/fba/fba_quantiser.hpp"
#include "fapcast/transport/asio.hpp"
#include "fapcast/transport/fba_track.hpp"
#include "fapcast/transport/track_file.hpp"
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"
#include "support/file_bytes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

namespace fapcast::test {
namespace {

using namespace std::chrono_literals;

// A free loopback port (bound once by the OS, then released for the command to bind).
int free_port() {
  asio::io_context io;
  udp::socket s(io, udp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
  return s.local_endpoint().port();
}

// `fapcast recv` into `out` on a free loopback port while `fapcast stream INPUT ARGS` sends to it.
// The receiver's idle timer runs from the moment it listens, so its --timeout must outlast the
// sender's start-up on a loaded sanitizer build (CI measured over 1 s): a receiver that gets the
// track ends on the sender's BYE long before it; one that refuses every packet waits it out.
constexpr const char* kReceiverTimeout = "10";
constexpr const char* kRefusingReceiverTimeout = "6";
struct Loopback {
  CommandResult send, recv;
  std::string recv_err;
};
Loopback stream_into_recv(const std::string& input, const std::string& args, const std::string& out,
                          const std::string& recv_args = "", const char* timeout = kReceiverTimeout) {
  const std::string dir = make_temp_dir("stream");
  const std::string url = "udp://127.0.0.1:" + std::to_string(free_port());
  Loopback r;
  std::thread receiver([&] {
    r.recv = run_command("(" + fapcast("recv " + url + " -o " + out + " --timeout " + timeout + " " + recv_args) + " 2>" + dir + "/recv.err)");
  });
  for (int i = 0; i < 100 && slurp(dir + "/recv.err").find("listening") == std::string::npos; ++i)
    std::this_thread::sleep_for(50ms);
  r.send = run_command(fapcast("stream " + input + " -o " + url + " --no-pace " + args));
  receiver.join();
  r.recv_err = slurp(dir + "/recv.err");
  return r;
}

const std::string kJoy = std::string(FAPCAST_TEST_DATA) + "/xface/joy.fap";

class StreamRecv : public testing::TestWithParam<const char*> {};

// By default the stream delivers the values sent: the Xface clip's head rotations are beyond the
// standard syntax's reach at fap_quant 0, so the fapcast profile carries it, and both ends say so.
TEST_P(StreamRecv, TheReceivedTrackEqualsTheSentOne) {
  const std::string out = make_temp_dir("stream-out") + "/out" + GetParam();
  const Loopback r = stream_into_recv(kJoy, "--iperiod 10", out);
  ASSERT_EQ(r.send.exit_code, 0) << r.send.err;
  ASSERT_EQ(r.recv.exit_code, 0) << r.recv_err;
  EXPECT_NE(r.recv.out.find("108 accepted, 0 lost"), std::string::npos) << r.recv.out;
  EXPECT_NE(r.send.out.find("sending:   fapcast profile at fap_quant 0: the values sent, losslessly (the standard "
                            "syntax cannot code frame "),
            std::string::npos)
      << r.send.out;
  EXPECT_NE(r.recv.out.find("received:  108 units fapcast profile, fap_quant 0 (the values sent, losslessly)"),
            std::string::npos)
      << r.recv.out;
  const auto sent = read_track_file(kJoy);
  const auto got = read_track_file(out);
  EXPECT_EQ(got.frames, sent.frames);
  EXPECT_EQ(got.rate, sent.rate);
}

// Only the standard syntax asked for: the smallest fap_quant that codes every value (the head
// rotations need 1), every value within half a step, and both ends say so.
TEST(StreamRecvCli, StandardOnlyIsWithinHalfAStep) {
  const std::string out = make_temp_dir("stream-out") + "/out.fap";
  const Loopback r = stream_into_recv(kJoy, "--iperiod 10 --profile standard", out);
  ASSERT_EQ(r.send.exit_code, 0) << r.send.err;
  ASSERT_EQ(r.recv.exit_code, 0) << r.recv_err;
  EXPECT_NE(r.send.out.find("sending:   standard FBA at fap_quant 1: every value within half a quantisation step"),
            std::string::npos)
      << r.send.out;
  EXPECT_NE(r.recv.out.find("received:  108 units standard FBA, fap_quant 1 (within half a step)"), std::string::npos)
      << r.recv.out;
  const auto sent = read_track_file(kJoy);
  const auto got = read_track_file(out);
  ASSERT_EQ(got.frames.size(), sent.frames.size());
  for (std::size_t k = 0; k < sent.frames.size(); ++k)
    for (int n = 3; n <= kFapCount; ++n)
      ASSERT_LE(2 * std::abs(std::int64_t{got.frames[k].value(n)} - sent.frames[k].value(n)), fba_step(n, 1)) << k << " " << n;
}
INSTANTIATE_TEST_SUITE_P(Formats, StreamRecv, testing::Values(".fap", ".fba", ".json"),
                         [](const auto& info) { return std::string(info.param + 1); });

TEST(StreamRecvCli, BadUsageAndBadInput) {
  EXPECT_EQ(run_command(fapcast("stream x.txt -o udp://127.0.0.1:9")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("recv udp://127.0.0.1:0 -o out.wav")).exit_code, 2);
  const auto missing = run_command(fapcast("stream /nonexistent/a.fap -o udp://127.0.0.1:9"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("/nonexistent/a.fap"), std::string::npos) << missing.err;
  const auto bad_url = run_command(fapcast("stream " + std::string(FAPCAST_TEST_DATA) + "/xface/joy.fap -o 127.0.0.1:9"));
  EXPECT_EQ(bad_url.exit_code, 2);  // a URL that is not udp://HOST:PORT is a usage mistake
  EXPECT_NE(bad_url.err.find("udp-url"), std::string::npos) << bad_url.err;
  const auto silent = run_command(fapcast("recv udp://127.0.0.1:0 -o /tmp/never.fap --timeout 0.2"));
  EXPECT_EQ(silent.exit_code, 1);
  EXPECT_NE(silent.err.find("no decodable frames"), std::string::npos) << silent.err;
}

// SRTP end to end (spec/rtp.md section 7): key files a (the receiver's) and b (another).
std::string srtp_keys() {
  const std::string dir = make_temp_dir("srtp-cli");
  std::ofstream(dir + "/a.key") << "inline:AAECAwQFBgcICQoLDA0ODxAREhMUFRYXGBkaGxwd\n";
  std::ofstream(dir + "/b.key") << "AQIDBAUGBwgJCgsMDQ4PEBESExQVFhcYGRobHB0e\n";
  return dir;
}

// Under the receiver's key the track arrives whole and every packet authenticates.
TEST(StreamRecvCli, SrtpUnderTheKeyArrivesWhole) {
  const std::string dir = srtp_keys();
  const std::string key_a = " --srtp-key-file " + dir + "/a.key";
  const Loopback good = stream_into_recv(kJoy, "--iperiod 10" + key_a, dir + "/good.fap", key_a);
  ASSERT_EQ(good.send.exit_code, 0) << good.send.err;
  ASSERT_EQ(good.recv.exit_code, 0) << good.recv_err;
  EXPECT_NE(good.recv.out.find("108 accepted, 0 lost"), std::string::npos) << good.recv.out;
  EXPECT_NE(good.recv.out.find(" 0 failed authentication, 0 replayed, 0 malformed"), std::string::npos) << good.recv.out;
  EXPECT_EQ(read_track_file(dir + "/good.fap").frames, read_track_file(kJoy).frames);
}

// A sender under another key delivers nothing: each packet refused before the RTP parser and
// counted on the srtp line; no output is written.
TEST(StreamRecvCli, SrtpUnderAnotherKeyIsRefusedAndCounted) {
  const std::string dir = srtp_keys();
  const Loopback other = stream_into_recv(kJoy, "--iperiod 10 --srtp-key-file " + dir + "/b.key", dir + "/other.fap",
                                          "--srtp-key-file " + dir + "/a.key", kRefusingReceiverTimeout);
  ASSERT_EQ(other.send.exit_code, 0) << other.send.err;
  EXPECT_EQ(other.recv.exit_code, 1) << other.recv.out;
  EXPECT_NE(other.recv_err.find("recv-no-frames"), std::string::npos) << other.recv_err;
  EXPECT_NE(other.recv.out.find("packets:   0 accepted"), std::string::npos) << other.recv.out;
  // 108 RTP packets under the wrong key (RTCP is refused earlier: no source was validated).
  EXPECT_NE(other.recv.out.find("srtp:      0 authenticated, 108 failed authentication"), std::string::npos)
      << other.recv.out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/other.fap"));
}

// A sender without a key (plain RTP, as a spoofer would send) delivers nothing either.
TEST(StreamRecvCli, PlainRtpIntoAnSrtpReceiverIsRefused) {
  const std::string dir = srtp_keys();
  const Loopback plain = stream_into_recv(kJoy, "--iperiod 10", dir + "/plain.fap", "--srtp-key-file " + dir + "/a.key",
                                          kRefusingReceiverTimeout);
  ASSERT_EQ(plain.send.exit_code, 0) << plain.send.err;
  EXPECT_EQ(plain.recv.exit_code, 1) << plain.recv.out;
  EXPECT_NE(plain.recv.out.find("packets:   0 accepted"), std::string::npos) << plain.recv.out;
  // The plain packets did arrive and were refused (not merely sent after the receiver left).
  EXPECT_EQ(plain.recv.out.find("srtp:      0 authenticated, 0 failed authentication"), std::string::npos)
      << plain.recv.out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/plain.fap"));
}

// A bad key file stops both commands before any socket work, with the key reader's message.
TEST(StreamRecvCli, BadSrtpKeyFilesNameTheFileAndTheRule) {
  const std::string bad = std::string(FAPCAST_TEST_DATA) + "/srtp/bad/";
  const auto recv = run_command(fapcast("recv udp://127.0.0.1:0 -o " + make_temp_dir("srtp-bad") +
                                        "/o.fap --srtp-key-file " + bad + "bad.001.srtp-key-base64.key"));
  EXPECT_EQ(recv.exit_code, 1);
  EXPECT_NE(recv.err.find(bad + "bad.001.srtp-key-base64.key: byte 38: srtp-key-base64: character 33 is not base64"),
            std::string::npos)
      << recv.err;
  EXPECT_EQ(recv.err.find("listening"), std::string::npos) << recv.err;
  const auto stream = run_command(fapcast("stream " + kJoy + " -o udp://127.0.0.1:9 --srtp-key-file " + bad +
                                          "bad.004.srtp-key-weak.key"));
  EXPECT_EQ(stream.exit_code, 1);
  EXPECT_NE(stream.err.find(bad + "bad.004.srtp-key-weak.key: byte 0: srtp-key-weak: every byte is the same"),
            std::string::npos)
      << stream.err;
  const auto missing = run_command(fapcast("stream " + kJoy + " -o udp://127.0.0.1:9 --srtp-key-file /nonexistent/k.key"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("/nonexistent/k.key"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace fapcast::test
