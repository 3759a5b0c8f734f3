// fapcast::Server under pressure (spec/serve.md, "Bounds"): the connection cap at accept, an
// accept that fails (no descriptor left) retried without spinning, refusals a client reads even
// while it is still sending its body, a deferred answer after the head's deadline, the waiting
// synthesis jobs of stopped sessions skipped, RTP sockets opened only when a session speaks.
#include "serve_support.hpp"

#include <gtest/gtest.h>

#include <dirent.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <ctime>
#include <filesystem>

namespace fapcast::test {
namespace {
using nlohmann::json;

std::size_t open_descriptors() {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator("/proc/self/fd")) ++n;
  return n;
}

std::chrono::milliseconds process_cpu_time() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return std::chrono::milliseconds(t.tv_sec * 1000 + t.tv_nsec / 1'000'000);
}

tcp::socket connect_to(asio::io_context& ioc, std::uint16_t port) {
  tcp::socket s(ioc);
  s.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  return s;
}

// Reads one response from a socket the test may not have written to.
Answer read_answer(tcp::socket& s) {
  beast::flat_buffer buffer;
  Answer a;
  beast::error_code ec;
  http::read(s, buffer, a.response, ec);
  a.status = ec ? 0 : static_cast<int>(a.response.result_int());
  a.body = a.response.body();
  return a;
}

std::string say_head(std::size_t content_length, bool with_token, const std::string& target = "/v1/say") {
  std::string head = "POST " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n";
  if (with_token) head += std::string("Authorization: Bearer ") + kToken + "\r\n";
  return head + "Content-Length: " + std::to_string(content_length) + "\r\n\r\n";
}

TEST(ServeHardening, ConnectionsOverTheCapGet503AtAcceptWithoutSendingAnything) {
  ServeConfig c = test_config();
  c.limits.max_connections = 2;
  c.limits.request_timeout = std::chrono::milliseconds(1500);  // without the cap at accept: a timeout, no answer
  TestServer server(c);
  asio::io_context ioc;
  tcp::socket a = connect_to(ioc, server.port());
  tcp::socket b = connect_to(ioc, server.port());
  tcp::socket over = connect_to(ioc, server.port());
  const auto t0 = std::chrono::steady_clock::now();
  const Answer refused = read_answer(over);
  EXPECT_EQ(refused.status, 503);
  EXPECT_EQ(refused.json()["error"], "too-many-connections");
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::milliseconds(1000));
  // A place freed is a place taken: once the server has seen `a` close, a request is served.
  a.close();
  int status = 0;
  for (int attempt = 0; attempt < 100 && status != 200; ++attempt) {
    status = get(server.port(), "/v1/stats").status;
    if (status != 200) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(status, 200);
}

// A refused connection closes lingering (reading what its peer still sends, up to 1 s): while it
// does, it is an open socket of the server's, counted in stats' connections_lingering (not in
// connections, which the cap is checked against); once the peer closes, it is gone.
TEST(ServeHardening, RefusedConnectionsAreCountedWhileTheyLinger) {
  ServeConfig c = test_config();
  c.limits.max_connections = 1;
  TestServer server(c);
  const auto wait_for = [&](std::size_t lingering, std::size_t connections) {
    for (int i = 0; i < 100; ++i) {
      const ServeStats s = server.server->stats();
      if (s.connections_lingering == lingering && s.connections == connections) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  };
  asio::io_context ioc;
  // Refused on the head (no token) with a body announced and not sent: the server answers 401
  // and lingers for the body.
  tcp::socket early = connect_to(ioc, server.port());
  asio::write(early, asio::buffer(say_head(10'000, false)));  // under the body limit: the token decides
  EXPECT_EQ(read_answer(early).status, 401);
  EXPECT_TRUE(wait_for(1, 0)) << "the 401's socket is not counted as lingering";
  early.close();  // the peer closes: the lingering read ends
  EXPECT_TRUE(wait_for(0, 0)) << "a lingering socket still counted after its peer closed";
  // Over the cap at accept: 503, lingering too.
  tcp::socket held = connect_to(ioc, server.port());
  EXPECT_TRUE(wait_for(0, 1));
  tcp::socket over = connect_to(ioc, server.port());
  EXPECT_EQ(read_answer(over).status, 503);
  EXPECT_TRUE(wait_for(1, 1)) << "the 503's socket is not counted as lingering";
  over.close();
  EXPECT_TRUE(wait_for(0, 1));
  held.close();
  EXPECT_TRUE(wait_for(0, 0));
}

TEST(ServeHardening, AcceptOutOfDescriptorsIsRetriedWithoutSpinning) {
  TestServer server;
  ASSERT_EQ(get(server.port(), "/v1/stats").status, 200);
  // That connection closed on the server's side too before descriptors run out: UBSan's checks
  // of a type not seen before open a pipe, and fail without a descriptor for it.
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_NOFILE, &saved), 0);
  // Every descriptor below a lowered limit taken.
  const rlim_t limit = static_cast<rlim_t>(open_descriptors()) + 64;
  rlimit low = saved;
  low.rlim_cur = std::min(limit, saved.rlim_cur);
  ASSERT_EQ(setrlimit(RLIMIT_NOFILE, &low), 0);
  // The client's socket (and the descriptors Asio opens with the first one) before the limit.
  asio::io_context ioc;
  tcp::socket client(ioc);
  client.open(tcp::v4());
  std::vector<int> fillers;
  for (int fd; (fd = open("/dev/null", O_RDONLY | O_CLOEXEC)) >= 0;) fillers.push_back(fd);
  ASSERT_FALSE(fillers.empty());
  // Queued in the listen backlog by the kernel: the server's accept() gets EMFILE.
  client.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server.port()));
  const auto cpu0 = process_cpu_time();
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  const auto cpu = process_cpu_time() - cpu0;
  for (const int fd : fillers) close(fd);
  ASSERT_EQ(setrlimit(RLIMIT_NOFILE, &saved), 0);
  // Re-arming at once would keep the network thread busy all the 400 ms.
  EXPECT_LT(cpu, std::chrono::milliseconds(150));
  // With descriptors back, the waiting connection is accepted and answered.
  const std::string head = std::string("GET /v1/stats HTTP/1.1\r\nHost: 127.0.0.1\r\nAuthorization: Bearer ") + kToken + "\r\n\r\n";
  asio::write(client, asio::buffer(head));
  EXPECT_EQ(read_answer(client).status, 200);
  bool logged = false;
  for (const std::string& line : server.log_lines()) logged = logged || line.find("accept:") != std::string::npos;
  EXPECT_TRUE(logged);
}

// The client writes its head, then its body while the server has answered on the head already
// (as a client does that does not read before it has sent all); then it reads. A close with the
// body unread resets the connection: the client's writes fail ("connection reset") and the
// answer is lost with them.
void expect_refusal_read_after_body(std::uint16_t port, std::size_t length, bool with_token, int status,
                                    const std::string& rule) {
  asio::io_context ioc;
  tcp::socket s = connect_to(ioc, port);
  asio::write(s, asio::buffer(say_head(length, with_token)));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the answer is on its way, the body not yet
  const std::string chunk(8 * 1024, ' ');
  beast::error_code ec;
  for (std::size_t sent = 0; sent < length && !ec; sent += chunk.size()) {
    asio::write(s, asio::buffer(chunk.data(), std::min(chunk.size(), length - sent)), ec);
    if (sent == 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));  // time for a reset to come back
  }
  EXPECT_FALSE(ec) << "sending the body: " << ec.message();
  const Answer a = read_answer(s);
  EXPECT_EQ(a.status, status);
  EXPECT_EQ(a.json()["error"], rule);
}

TEST(ServeHardening, RefusalOnTheHeadIsReadWhileTheClientSendsABigBody) {
  TestServer server;
  // Within the body limit but never read: the token is refused on the head.
  expect_refusal_read_after_body(server.port(), 16000, false, 401, "token-missing");
  // Past the limit (from its Content-Length), with or without a token.
  expect_refusal_read_after_body(server.port(), 256 * 1024, true, 413, "body-too-large");
}

TEST(ServeHardening, DeferredAnswerIsWrittenAfterTheHeadsDeadline) {
  ServeConfig c = test_config();
  c.limits.request_timeout = std::chrono::milliseconds(40);  // shorter than the first piece's synthesis
  c.sentence_bytes = 2000;
  TestServer server(c);
  std::string text;
  for (int i = 0; i < 6; ++i) text += "The quick brown fox jumps over the lazy dog, and then it runs far away into the woods. ";
  asio::io_context ioc;
  tcp::socket s = connect_to(ioc, server.port());
  const std::string body = json{{"text", text}, {"channel", "late"}}.dump();
  asio::write(s, asio::buffer(say_head(body.size(), true) + body));
  const Answer a = read_answer(s);
  ASSERT_EQ(a.status, 202) << a.body;
  EXPECT_GT(a.json()["first_frame_ms"].get<double>(), 40.0) << "the answer did not come after the head's deadline";
}

TEST(ServeHardening, StoppedSessionsSkipTheirWaitingSynthesis) {
  ServeConfig c = test_config();
  c.synthesis_threads = 1;
  TestServer server(c);
  const std::string sentence = "The quick brown fox jumps over the lazy dog, and then it runs far away into the woods.";
  // Eight barge-ins sent at once: each stops the one before; only the first (running when the
  // others come) and the last need synthesising.
  constexpr int kSays = 8;
  asio::io_context ioc;
  std::vector<tcp::socket> sockets;
  for (int i = 0; i < kSays; ++i) {
    sockets.push_back(connect_to(ioc, server.port()));
    const std::string body = json{{"text", sentence}, {"channel", "storm"}, {"interrupt", true}}.dump();
    asio::write(sockets.back(), asio::buffer(say_head(body.size(), true) + body));
  }
  int spoke = 0;
  for (auto& s : sockets) {
    const Answer a = read_answer(s);
    EXPECT_EQ(a.status, 202) << a.body;
    spoke += a.json()["state"] == "speaking" || a.json()["state"] == "done" ? 1 : 0;
  }
  EXPECT_GE(spoke, 1);
  const json stats = get(server.port(), "/v1/stats").json();
  EXPECT_LE(stats["sentences_synthesised"].get<int>(), 4) << stats.dump();
  EXPECT_GE(stats["sentences_synthesised"].get<int>(), 1) << stats.dump();
}

TEST(ServeHardening, QueuedSessionsHoldNoRtpSockets) {
  ServeConfig c = test_config();
  TestServer server(c);
  const std::string sentence = "The quick brown fox jumps over the lazy dog, and then it runs far away into the woods.";
  asio::io_context ioc;
  tcp::socket first = connect_to(ioc, server.port());
  const std::string body = json{{"text", sentence + " " + sentence}, {"channel", "fds"}}.dump();
  asio::write(first, asio::buffer(say_head(body.size(), true) + body));
  ASSERT_EQ(read_answer(first).status, 202);
  const std::size_t before = open_descriptors();
  json rtp = json::array();
  for (int d = 0; d < 4; ++d) rtp.push_back("udp://127.0.0.1:" + std::to_string(41000 + 4 * d));
  std::vector<std::string> ids;
  for (int i = 0; i < 4; ++i) {
    const Answer a = post(server.port(), "/v1/say", json{{"text", "Hi."}, {"channel", "fds"}, {"rtp", rtp}}.dump());
    ASSERT_EQ(a.status, 202) << a.body;
    EXPECT_EQ(a.json()["state"], "queued");
    ids.push_back(a.json()["session"].get<std::string>());
  }
  // 4 sessions x 4 destinations x 4 sockets would be 64 descriptors.
  EXPECT_LT(open_descriptors(), before + 8);
  for (const std::string& id : ids) EXPECT_EQ(post(server.port(), "/v1/sessions/" + id + "/stop", "").status, 200);
}

}  // namespace
}  // namespace fapcast::test
