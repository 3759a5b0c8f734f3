// A bounded soak of a real Server on loopback (about 6 s): live WebSocket clients connect, read
// part of a stream, drop without closing or close cleanly and reconnect, while requests speak on
// their channel, most of them barging in on the one speaking, some queued, some to an RTP
// receiver. Afterwards the server's counters of what it holds now return to zero (no
// connection, client, session speaking or queued) while those of what happened show that it
// did; ASan (the CI build) reports any leak when the process ends.
#include "fapcast/serve/server.hpp"
#include "serve/serve_support.hpp"
#include "support/serve_client.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace fapcast {
namespace {

TEST(ServeSoak, ClientsDropAndReconnectSessionsBargeInNothingIsLeft) {
  test::TestServer running;
  const Server& server = *running.server;
  const std::uint16_t port = running.port();
  test::RtpPorts sink;

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  std::atomic<int> frames_seen{0}, reconnects{0}, said{0}, refused{0};
  std::vector<std::thread> clients;
  for (int c = 0; c < 4; ++c)
    clients.emplace_back([&, c] {
      std::mt19937 random(static_cast<unsigned>(c));
      while (std::chrono::steady_clock::now() < deadline) {
        test::DroppingLiveClient client(port, test::kToken, "soak");
        ++reconnects;
        const int keep = static_cast<int>(random() % 40);  // messages before it goes
        std::string message;
        bool binary = false;
        for (int m = 0; m < keep && client.read(message, binary, std::chrono::milliseconds(500)); ++m)
          if (binary) ++frames_seen;
        if (random() % 2) client.drop();
        else client.close();
      }
    });
  std::thread speaker([&] {
    const char* texts[] = {"Bob sees the red boat.", "How good.", "We go. Father is here."};
    for (int i = 0; std::chrono::steady_clock::now() < deadline; ++i) {
      nlohmann::json body = {{"text", texts[i % 3]}, {"channel", "soak"}, {"interrupt", i % 4 != 3}};
      if (i % 5 == 0) body["rtp"] = sink.url();
      const auto a = test::http_exchange(port, test::json_request("POST", "/v1/say", test::kToken, body.dump()));
      if (!a.empty() && a[0].status == 202) ++said;
      else ++refused;
      sink.drain();
      std::this_thread::sleep_for(std::chrono::milliseconds(150));
    }
  });
  speaker.join();
  for (auto& t : clients) t.join();

  // What is left speaking ends within its last sentences; every connection is closed by then.
  ServeStats s;
  for (int i = 0; i < 100; ++i) {
    s = server.stats();
    if (s.connections == 0 && s.connections_lingering == 0 && s.clients == 0 && s.sessions_speaking == 0 &&
        s.sessions_queued == 0)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(s.connections, 0u);
  EXPECT_EQ(s.connections_lingering, 0u);
  EXPECT_EQ(s.clients, 0u);
  EXPECT_EQ(s.sessions_speaking, 0u);
  EXPECT_EQ(s.sessions_queued, 0u);
  // ... and it did what it was asked.
  EXPECT_GT(said.load(), 10);
  EXPECT_GT(s.sessions_started, 5u);
  EXPECT_GT(s.sessions_stopped, 0u) << "no barge-in stopped a session";
  EXPECT_GE(s.clients_accepted, static_cast<std::uint64_t>(reconnects.load()));
  EXPECT_GT(reconnects.load(), 8);
  EXPECT_GT(frames_seen.load(), 0);
  EXPECT_GT(s.rtp_packets, 0u);
  // Every session accepted ended, spoken to the end, stopped (barge-in, before or after its first
  // frame) or failed: none is held.
  EXPECT_EQ(static_cast<std::uint64_t>(said.load()), s.sessions_done + s.sessions_stopped + s.sessions_failed);
  EXPECT_LE(s.sessions_started, s.sessions_done + s.sessions_stopped + s.sessions_failed);

  running.stop();
  const ServeStats end = server.stats();
  EXPECT_EQ(end.connections, 0u);
  EXPECT_EQ(end.connections_lingering, 0u);
  EXPECT_EQ(end.clients, 0u);
}

}  // namespace
}  // namespace fapcast
