// The frames of a session are sent by the server's frame pacer (serve/src/frame_pacer.hpp), a
// thread of their own: what the network thread does meanwhile (here: nothing but a handler that
// keeps it for 600 ms, as a burst of requests would) does not hold them back. The old design,
// which sent them from the network thread, sends none in that window.
#include "fapcast/serve/server.hpp"
#include "serve/serve_support.hpp"
#include "support/serve_client.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
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

// The id of this process's thread named `name`, waited for up to 5 s (a thread names itself
// once it runs); 0 when there is none.
pid_t thread_named(const std::string& name) {
  for (const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5); std::chrono::steady_clock::now() < until;
       std::this_thread::sleep_for(std::chrono::milliseconds(10))) {
    for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
      std::ifstream comm(task.path() / "comm");
      std::string n;
      if (std::getline(comm, n) && n == name) return static_cast<pid_t>(std::stol(task.path().filename().string()));
    }
  }
  return 0;
}

// Whether this process may put a thread in SCHED_FIFO at `priority` (CAP_SYS_NICE or RLIMIT_RTPRIO).
bool may_run_realtime(int priority) {
  int rc = -1;
  std::thread probe([&] {
    sched_param p{};
    p.sched_priority = priority;
    rc = pthread_setschedparam(pthread_self(), SCHED_FIFO, &p);
  });
  probe.join();
  return rc == 0;
}

bool logged(test::TestServer& server, const std::string& part) {
  for (const std::string& line : server.log_lines())
    if (line.find(part) != std::string::npos) return true;
  return false;
}

TEST(ServePacing, ThePacerIsInTheDefaultClassUnlessAsked) {
  test::TestServer server;
  const pid_t pacer = thread_named("fapcast-pacer");
  ASSERT_NE(pacer, 0);
  EXPECT_EQ(sched_getscheduler(pacer), SCHED_OTHER);
  EXPECT_EQ(test::get(server.port(), "/v1/stats").json()["pacer_priority"], 0);
  EXPECT_FALSE(logged(server, "frame pacer"));
}

// --pacer-priority 7: the pacer's thread in SCHED_FIFO at 7, said in the log and in the stats, and
// frames still sent; where the system refuses (no CAP_SYS_NICE, RLIMIT_RTPRIO below 7) the log
// says so with the reason and the server runs on in the default class. (ServeCli's
// PacerPriorityRefusedIsLoggedAndServes makes the refusal happen as root.)
TEST(ServePacing, ThePacerRunsAtTheRealTimePriorityAskedForOrTheLogSaysWhyNot) {
  const bool permitted = may_run_realtime(7);
  ServeConfig c = test::test_config();
  c.pacer_priority = 7;
  test::TestServer server(c);
  const pid_t pacer = thread_named("fapcast-pacer");
  ASSERT_NE(pacer, 0);
  sched_param param{};
  ASSERT_EQ(sched_getparam(pacer, &param), 0);
  const nlohmann::json stats = test::get(server.port(), "/v1/stats").json();
  if (permitted) {
    EXPECT_EQ(sched_getscheduler(pacer), SCHED_FIFO);
    EXPECT_EQ(param.sched_priority, 7);
    EXPECT_EQ(stats["pacer_priority"], 7) << stats.dump();
    EXPECT_TRUE(logged(server, "fapcast serve: frame pacer at real-time priority 7 (SCHED_FIFO)"));
  } else {
    EXPECT_EQ(sched_getscheduler(pacer), SCHED_OTHER);
    EXPECT_EQ(stats["pacer_priority"], 0) << stats.dump();
    EXPECT_TRUE(logged(server, "real-time priority 7 (SCHED_FIFO) refused: "));
  }
  // The network thread stays in the default class: only the pacer is raised.
  int policy = -1;
  ASSERT_EQ(pthread_getschedparam(server.thread.native_handle(), &policy, &param), 0);
  EXPECT_EQ(policy, SCHED_OTHER);
  test::RtpPorts sink;
  const test::Answer a =
      test::post(server.port(), "/v1/say", nlohmann::json{{"text", "Hello there."}, {"channel", "rt"}, {"rtp", sink.url()}}.dump());
  ASSERT_EQ(a.status, 202) << a.body;
  EXPECT_TRUE(sink.receive(0, std::chrono::seconds(2)));  // an animation packet
}

}  // namespace
}  // namespace fapcast
