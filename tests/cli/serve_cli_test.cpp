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

TEST(ServeCli, PrintsItsUrlAnswersAndExitsZeroOnSigterm) {
  const std::string dir = make_temp_dir("serve_cli");
  write_file_atomically(dir + "/token", std::string(kToken) + "\n");
  std::filesystem::create_directories(dir + "/three");
  write_file_atomically(dir + "/three/three.module.js", "// three\n");
  const std::string voice = spoken_voice_file().string();
  int out[2];
  ASSERT_EQ(pipe(out), 0);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  posix_spawn_file_actions_addopen(&actions, 2, (dir + "/err.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const std::string token_file = dir + "/token", three = dir + "/three";
  std::vector<std::string> args = {FAPCAST_EXE, "serve", "--listen", "127.0.0.1:0", "--token-file", token_file,
                                   "--voice", voice, "--three-dir", three};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, FAPCAST_EXE, &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  const std::string url = read_line(out[0], std::chrono::seconds(20));
  close(out[0]);
  ASSERT_EQ(url.rfind("http://127.0.0.1:", 0), 0u) << url;
  const int port = std::stoi(url.substr(std::string("http://127.0.0.1:").size()));
  EXPECT_GT(port, 0);
  {
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
    EXPECT_EQ(res.result_int(), 200u);
    EXPECT_NE(res.body().find("\"requests\":1"), std::string::npos) << res.body();
  }
  ASSERT_EQ(kill(pid, SIGTERM), 0);
  int status = -1;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (waitpid(pid, &status, WNOHANG) == 0) {
    ASSERT_LT(std::chrono::steady_clock::now(), until) << "still running 10 s after SIGTERM";
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const std::string err = read_file(dir + "/err.txt");
  EXPECT_NE(err.find("\"GET /v1/stats\" 200"), std::string::npos) << err;
  EXPECT_NE(err.find("fapcast serve: stopping"), std::string::npos) << err;
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
}

}  // namespace
}  // namespace fapcast::test
