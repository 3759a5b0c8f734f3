// `fapcast serve` end to end (spec/serve.md): on port 0 it prints its URL as the first line of
// standard output, answers on it, logs one line per request on standard error, and exits 0 on
// SIGTERM; bad usage is exit 2, a bad token file exit 1.
#include "fapcast_command.hpp"
#include "support/run_command.hpp"
#include "support/spoken_voice.hpp"

#include "fapcast/core/file_io.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <utility>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace fapcast::test {
namespace {
namespace http = boost::beast::http;
using tcp = boost::asio::ip::tcp;

constexpr const char* kToken = "cli-serve-token-0123456789";

std::string q(const std::string& s) { return "'" + s + "'"; }

// Reads a line from `fd` within `timeout`.
std::string read_line(int fd, std::chrono::milliseconds timeout) {
  std::string line;
  const auto until = std::chrono::steady_clock::now() + timeout;
  char c = 0;
  while (std::chrono::steady_clock::now() < until) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 50) <= 0) continue;
    if (read(fd, &c, 1) != 1 || c == '\n') break;
    line += c;
  }
  return line;
}

// A `fapcast serve` started by argv (argv[0] the program run), standard error to `err_path`.
struct ServeProcess {
  pid_t pid = 0;
  std::string url;  // its first line of standard output, within 20 s

  ServeProcess(std::vector<std::string> args, const std::string& err_path) {
    int out[2];
    if (pipe(out) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid = 0;
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    if (pid != 0) url = read_line(out[0], std::chrono::seconds(20));
    close(out[0]);
  }
  // SIGTERM, then its wait status (-1: still running 10 s later, then killed).
  int stop() {
    if (pid == 0 || kill(pid, SIGTERM) != 0) return -1;
    int status = -1;
    for (const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10); waitpid(pid, &status, WNOHANG) == 0;
         std::this_thread::sleep_for(std::chrono::milliseconds(10))) {
      if (std::chrono::steady_clock::now() > until) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        status = -1;
        break;
      }
    }
    pid = 0;
    return status;
  }
  ~ServeProcess() { stop(); }
};

// GET /v1/stats on `port`: status and body.
std::pair<unsigned, std::string> get_stats(int port) {
  boost::asio::io_context io;
  tcp::socket s(io);
  s.connect(tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), static_cast<std::uint16_t>(port)));
  http::request<http::empty_body> req{http::verb::get, "/v1/stats", 11};
  req.set(http::field::host, "127.0.0.1");
  req.set(http::field::authorization, std::string("Bearer ") + kToken);
  http::write(s, req);
  boost::beast::flat_buffer b;
  http::response<http::string_body> res;
  http::read(s, b, res);
  return {res.result_int(), res.body()};
}

int port_of(const std::string& url) { return std::stoi(url.substr(std::string("http://127.0.0.1:").size())); }

std::string serve_dir(const std::string& name) {
  const std::string dir = make_temp_dir(name);
  write_file_atomically(dir + "/token", std::string(kToken) + "\n");
  std::filesystem::create_directories(dir + "/three");
  write_file_atomically(dir + "/three/three.module.js", "// three\n");
  return dir;
}

TEST(ServeCli, PrintsItsUrlAnswersAndExitsZeroOnSigterm) {
  const std::string dir = serve_dir("serve_cli");
  ServeProcess serve({FAPCAST_EXE, "serve", "--listen", "127.0.0.1:0", "--token-file", dir + "/token", "--voice",
                      spoken_voice_file().string(), "--three-dir", dir + "/three"},
                     dir + "/err.txt");
  ASSERT_NE(serve.pid, 0);
  ASSERT_EQ(serve.url.rfind("http://127.0.0.1:", 0), 0u) << serve.url;
  const int port = port_of(serve.url);
  EXPECT_GT(port, 0);
  const auto [status_code, body] = get_stats(port);
  EXPECT_EQ(status_code, 200u);
  EXPECT_NE(body.find("\"requests\":1"), std::string::npos) << body;
  const int status = serve.stop();
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const std::string err = read_file(dir + "/err.txt");
  EXPECT_NE(err.find("\"GET /v1/stats\" 200"), std::string::npos) << err;
  EXPECT_NE(err.find("fapcast serve: stopping"), std::string::npos) << err;
}

// --pacer-priority where the system refuses SCHED_FIFO: run without CAP_SYS_NICE (dropped from
// the bounding set by util-linux's setpriv, so even root lacks it) and with RLIMIT_RTPRIO 0. The
// server says so on standard error at start, serves, and reports priority 0 in its stats.
TEST(ServeCli, PacerPriorityRefusedIsLoggedAndServes) {
  const std::string dir = serve_dir("serve_cli_rt");
  std::vector<std::string> args = {"sh", "-c", "ulimit -r 0 && exec \"$@\"", "sh"};
  if (geteuid() == 0)  // a user without the capability needs nothing dropped (nor may drop it)
    for (const char* a : {"setpriv", "--bounding-set", "-sys_nice", "--inh-caps", "-sys_nice"}) args.emplace_back(a);
  for (const std::string& a : {std::string(FAPCAST_EXE), std::string("serve"), std::string("--listen"), std::string("127.0.0.1:0"),
                               std::string("--token-file"), dir + "/token", std::string("--voice"), spoken_voice_file().string(),
                               std::string("--three-dir"), dir + "/three", std::string("--pacer-priority"), std::string("30")})
    args.push_back(a);
  ServeProcess serve(args, dir + "/err.txt");
  ASSERT_EQ(serve.url.rfind("http://127.0.0.1:", 0), 0u) << serve.url << read_file(dir + "/err.txt");
  const auto [status_code, body] = get_stats(port_of(serve.url));
  EXPECT_EQ(status_code, 200u);
  EXPECT_NE(body.find("\"pacer_priority\":0"), std::string::npos) << body;
  const int status = serve.stop();
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const std::string err = read_file(dir + "/err.txt");
  EXPECT_NE(err.find("fapcast serve: frame pacer: real-time priority 30 (SCHED_FIFO) refused: Operation not permitted "
                     "(it needs CAP_SYS_NICE or RLIMIT_RTPRIO >= 30); running at the default priority"),
            std::string::npos)
      << err;
}

TEST(ServeCli, UsageAndBadInput) {
  const std::string dir = make_temp_dir("serve_cli_bad");
  const auto no_token = run_command(fapcast("serve --listen 127.0.0.1:0"));
  EXPECT_EQ(no_token.exit_code, 2) << no_token.err;
  EXPECT_NE(no_token.err.find("--token-file"), std::string::npos);
  const auto bad_listen = run_command(fapcast("serve --listen nowhere --token-file x"));
  EXPECT_EQ(bad_listen.exit_code, 2) << bad_listen.err;
  // Names are not resolved: a name where the address goes is usage too.
  const auto name = run_command(fapcast("serve --listen localhost:0 --token-file x"));
  EXPECT_EQ(name.exit_code, 2) << name.err;
  EXPECT_NE(name.err.find("numeric"), std::string::npos) << name.err;
  write_file_atomically(dir + "/short", "abc\n");
  const auto short_token =
      run_command(fapcast("serve --listen 127.0.0.1:0 --voice " + q(spoken_voice_file().string()) + " --token-file " +
                          q(dir + "/short")));
  EXPECT_EQ(short_token.exit_code, 1) << short_token.err;
  EXPECT_NE(short_token.err.find(dir + "/short"), std::string::npos) << short_token.err;
  // SCHED_FIFO's priorities are 1..99 (0: the default class).
  for (const char* bad : {"100", "-1", "high"}) {
    const auto r = run_command(fapcast(std::string("serve --listen 127.0.0.1:0 --token-file x --pacer-priority ") + bad));
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.err;
    EXPECT_NE(r.err.find("--pacer-priority"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace fapcast::test
