// The frames of a session are sent by the server's frame pacer (serve/src/frame_pacer.hpp), a
// thread of their own: what the network thread does meanwhile (here: nothing but a handler that
// keeps it for 600 ms, as a burst of requests would) does not hold them back. The old design,
// which sent them from the network thread, sends none in that window.
#include "fapcast/serve/server.hpp"
#include "serve/serve_support.hpp"
#include "support/serve_client.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

namespace fapcast {
namespace {

TEST(ServePacing, FramesLeaveWhileTheNetworkThreadIsBusy) {
  test::TestServer server;
  test::RtpPorts sink;
  const std::string text =
      "This sentence goes on for long enough to be still speaking while the network thread is kept busy.";
  const test::Answer a = test::post(server.port(), "/v1/say",
                                    nlohmann::json{{"text", text}, {"channel", "pacing"}, {"rtp", sink.url()}}.dump());
  ASSERT_EQ(a.status, 202) << a.body;  // answered at its first frame
  std::atomic<int> phase{0};  // 1 while the network thread is kept, 2 after
  asio::post(server.io, [&phase] {
    phase = 1;
    std::this_thread::sleep_for(std::chrono::milliseconds(600));
    phase = 2;
  });
  while (phase == 0) std::this_thread::yield();
  sink.drain();
  std::size_t during = 0;
  while (phase == 1)
    if (sink.receive(0, std::chrono::milliseconds(20)) && phase == 1) ++during;  // P: animation RTP only
  // 15 frames are due in 600 ms at 25 fps; a loaded machine may delay some, not all.
  EXPECT_GE(during, 5u);
  const nlohmann::json status = test::get(server.port(), "/v1/sessions/" + a.json()["session"].get<std::string>()).json();
  EXPECT_EQ(status["state"], "speaking") << status.dump();  // the window was inside the session
}

}  // namespace
}  // namespace fapcast
