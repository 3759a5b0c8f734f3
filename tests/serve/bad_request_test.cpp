// The named bad requests of tests/data/serve/bad: each NAME.http (raw bytes: one request, or
// several on one connection when the refusal needs a server that is busy) is sent over a real
// loopback TCP connection to a real Server, and the last answer's status, rule and detail are
// compared with the golden line "NAME: STATUS RULE: DETAIL" of expected-answers.txt. Also the
// start-up refusals: a bad SRTP key file and a bad token file stop the Server (and `fapcast
// serve`, exit 1) with the file named.
#include "fapcast/core/file_io.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/serve/server.hpp"
#include "fapcast/voice/voice.hpp"
#include "support/bad_inputs.hpp"
#include "support/run_command.hpp"
#include "serve/serve_support.hpp"
#include "support/serve_client.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace fapcast {
namespace {

const std::filesystem::path kBad = std::filesystem::path(FAPCAST_TEST_DATA) / "serve" / "bad";
constexpr const char* kToken = "c2VjcmV0LXRva2VuLWZvci10ZXN0cw";  // what the .http files present

// The config of every server here: the tests' (serve_support.hpp) with the token the .http
// files present and the limits the stateful requests reach: two sessions in all, no queue.
ServeConfig bad_request_config() {
  static const std::filesystem::path dir = test::make_temp_dir("serve_bad_requests");
  write_file_atomically(dir / "token", std::string(kToken) + "\n");
  ServeConfig c = test::test_config();
  c.token_file = dir / "token";
  c.limits.max_sessions = 2;
  c.limits.max_queue = 0;
  return c;
}

// The number of requests in a file: each has one request line ending in " HTTP/1.1" (no body
// of these files holds that).
std::size_t request_count(const std::string& raw) {
  std::size_t n = 0;
  for (auto at = raw.find(" HTTP/1.1\r\n"); at != std::string::npos; at = raw.find(" HTTP/1.1\r\n", at + 1)) ++n;
  return n;
}

class BadRequest : public testing::TestWithParam<std::string> {};

TEST_P(BadRequest, AnswersItsGoldenStatusRuleAndDetail) {
  const std::string name = GetParam();
  const auto golden = test::golden_lines(kBad / "expected-answers.txt");
  const std::string raw = test::slurp(kBad / name);
  test::TestServer server(bad_request_config());
  const std::size_t n = request_count(raw);
  ASSERT_GE(n, 1u);
  const auto answers = test::http_exchange(server.port(), raw, n);
  ASSERT_EQ(answers.size(), n) << name << ": " << (answers.empty() ? "" : answers.back().error);
  for (std::size_t i = 0; i + 1 < n; ++i)
    EXPECT_EQ(answers[i].status, 202) << name << " request " << i + 1 << ": " << answers[i].body;
  const auto& last = answers.back();
  const auto body = nlohmann::json::parse(last.body, nullptr, false);
  ASSERT_TRUE(body.is_object()) << name << ": " << last.status << " " << last.body;
  const std::string line = name + ": " + std::to_string(last.status) + " " + body.value("error", "?") + ": " +
                           body.value("detail", "?");
  EXPECT_EQ(line, golden.count(name) ? golden.at(name) : name + " has no line in expected-answers.txt");
  // Refused and counted; a lone request refused before any work started nothing.
  const ServeStats s = server.server->stats();
  EXPECT_EQ(s.unauthorized + s.forbidden + s.bad_requests + s.over_limits, 1u) << name;
  if (n == 1) {
    EXPECT_EQ(s.sessions_started, 0u) << name;
  }
}

std::vector<std::string> http_files() { return test::bad_input_names(kBad, ".http"); }

INSTANTIATE_TEST_SUITE_P(Serve, BadRequest, testing::ValuesIn(http_files()),
                         [](const testing::TestParamInfo<std::string>& info) { return test::test_name_of(info.param); });

TEST(BadRequest, EveryGoldenLineHasItsRequest) {
  for (const auto& [name, line] : test::golden_lines(kBad / "expected-answers.txt"))
    if (name.ends_with(".http")) {
      EXPECT_TRUE(std::filesystem::exists(kBad / name)) << line;
    }
}

// A start-up refusal: the Server's exception, whose message names the file and the rule.
std::string startup_error(ServeConfig config) {
  ServeVoices voices;
  voices.emplace("default", test::serve_test_voice());
  asio::io_context io;
  try {
    Server server(io, std::move(config), std::move(voices));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(started)";
}

TEST(BadRequest, BadSrtpKeyFileStopsTheServerAtStart) {
  const auto golden = test::golden_lines(kBad / "expected-answers.txt");
  for (const char* key : {"bad.002.srtp-key-length.key", "bad.004.srtp-key-weak.key"}) {
    ServeConfig c = bad_request_config();
    c.srtp_key_file = std::filesystem::path(FAPCAST_TEST_DATA) / "srtp" / "bad" / key;
    const std::string message = startup_error(c);
    const std::string name = std::string("srtp-key-file ") + key;
    const auto at = message.find(key);
    ASSERT_NE(at, std::string::npos) << message;
    EXPECT_EQ(name + ": " + message.substr(at), golden.count(name) ? golden.at(name) : name + ": no golden line");
  }
}

TEST(BadRequest, BadTokenFileStopsTheServerAtStart) {
  const std::filesystem::path dir = test::make_temp_dir("serve_bad_token");
  write_file_atomically(dir / "short.token", "abc\n");
  ServeConfig c = bad_request_config();
  c.token_file = dir / "short.token";
  const std::string message = startup_error(c);
  EXPECT_NE(message.find("short.token"), std::string::npos) << message;
  EXPECT_NE(message.find("serve-token"), std::string::npos) << message;
  // Longer than any token: the same rule at the byte where the token must end (serve_bearer_token_fuzz's
  // finding: it was a read failure without a rule).
  write_file_atomically(dir / "long.token", std::string(600, 'a') + "\n");
  c.token_file = dir / "long.token";
  const std::string long_message = startup_error(c);
  EXPECT_NE(long_message.find("long.token: byte 512: serve-token: 601 bytes"), std::string::npos) << long_message;
}

// serve_config_fuzz's finding: a host with a bracket inside did not print back to itself.
TEST(BadRequest, ListenAddressRefusesBracketsAndBlanksInTheHost) {
  EXPECT_FALSE(parse_listen_address("[[x]:4"));
  EXPECT_FALSE(parse_listen_address("a]b:80"));
  EXPECT_FALSE(parse_listen_address("local host:80"));
  EXPECT_FALSE(parse_listen_address(std::string("a\0b:80", 6)));
  ASSERT_TRUE(parse_listen_address("[::1]:8080"));
  EXPECT_EQ(parse_listen_address("[::1]:8080")->host, "::1");
  EXPECT_EQ(parse_listen_address("localhost:80")->host, "localhost");
}

}  // namespace
}  // namespace fapcast
