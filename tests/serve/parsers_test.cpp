// The serve library's parsers on their own (spec/serve.md): the live frame's byte layout both
// ways, the bearer token and its presentations, the configuration file, the say request's
// pieces.
#include "fapcast/core/input_error.hpp"
#include "fapcast/serve/bearer_token.hpp"
#include "fapcast/serve/live_message.hpp"
#include "fapcast/serve/say_request.hpp"
#include "fapcast/serve/serve_config.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace fapcast {
namespace {

std::span<const std::uint8_t> bytes(const std::string& s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

TEST(LiveFrame, LayoutIsTheDocumentedOneAndRoundTrips) {
  const std::vector<float> w = {0.5f, -1.25f, 3.0f};
  const std::vector<std::int16_t> audio = {1, -2, 300, -32768, 32767};
  std::string m;
  encode_live_frame(w, audio, 7, 123456789012LL, 42, true, m);
  ASSERT_EQ(m.size(), kLiveFrameHeaderBytes + 4 * w.size() + 2 * audio.size());
  EXPECT_EQ(static_cast<std::uint8_t>(m[0]), kLiveFrameType);
  EXPECT_EQ(static_cast<std::uint8_t>(m[1]), 1);
  EXPECT_EQ(static_cast<std::uint8_t>(m[2]) | static_cast<std::uint8_t>(m[3]) << 8, 3);  // K, little-endian
  std::int64_t sample = 0;
  std::memcpy(&sample, m.data() + 8, 8);
  EXPECT_EQ(sample, 123456789012LL);
  float w1 = 0;
  std::memcpy(&w1, m.data() + 24 + 4, 4);
  EXPECT_EQ(w1, -1.25f);
  std::int16_t a3 = 0;
  std::memcpy(&a3, m.data() + 24 + 12 + 6, 2);
  EXPECT_EQ(a3, -32768);
  LiveFrame f;
  ASSERT_FALSE(decode_live_frame(bytes(m), f));
  EXPECT_EQ(f, (LiveFrame{true, 7, 123456789012LL, 42, w, audio}));
}

TEST(LiveFrame, RefusesWrongTypeAndLengths) {
  std::string m;
  encode_live_frame(std::vector<float>{1.0f}, std::vector<std::int16_t>{1, 2}, 1, 0, 0, false, m);
  LiveFrame f;
  EXPECT_EQ(decode_live_frame(bytes(m.substr(0, m.size() - 1)), f), std::errc::invalid_argument);
  EXPECT_EQ(decode_live_frame(bytes(m + "x"), f), std::errc::invalid_argument);
  std::string wrong = m;
  wrong[0] = 2;
  EXPECT_EQ(decode_live_frame(bytes(wrong), f), std::errc::invalid_argument);
  std::string many = m;
  many[2] = static_cast<char>(0xff);
  many[3] = static_cast<char>(0xff);  // 65535 weights: above kLiveMaxWeights
  EXPECT_EQ(decode_live_frame(bytes(many), f), std::errc::value_too_large);
}

TEST(BearerTokenTest, MatchesOnlyItselfAndRefusesWeakTokens) {
  const BearerToken t("abcdefghijklmnop-1234", "token-file");
  EXPECT_TRUE(t.matches("abcdefghijklmnop-1234"));
  EXPECT_FALSE(t.matches("abcdefghijklmnop-123"));
  EXPECT_FALSE(t.matches("abcdefghijklmnop-12345"));
  EXPECT_FALSE(t.matches(""));
  try {
    BearerToken("short", "token-file");
    FAIL() << "a 5-character token was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "serve-token");
    EXPECT_NE(std::string(e.what()).find("token-file"), std::string::npos);
  }
  EXPECT_THROW(BearerToken("abcdefghijklmnop/1234", "t"), InputError);  // '/' is not a token character
}

TEST(BearerTokenTest, Presentations) {
  EXPECT_EQ(bearer_credentials("Bearer abc"), "abc");
  EXPECT_EQ(bearer_credentials("bearer abc"), "abc");
  EXPECT_FALSE(bearer_credentials("Basic abc"));
  EXPECT_EQ(subprotocol_token("fapcast.v1, bearer.abcdefghijklmnop"), "abcdefghijklmnop");
  EXPECT_TRUE(offers_live_subprotocol("chat, fapcast.v1"));
  EXPECT_FALSE(offers_live_subprotocol("chat"));
}

TEST(ServeConfigTest, KeysAppliedAndRefusedByName) {
  ServeConfig c;
  apply_serve_config(R"({"listen":"[::1]:0","token_file":"t.txt","rtp_networks":["10.0.0.0/8"],
                         "sentence_bytes":64,"pacer_priority":20,"limits":{"max_queue":3}})",
                     "serve.json", "/etc/fapcast", c);
  EXPECT_EQ(c.host, "::1");
  EXPECT_EQ(c.port, 0);
  EXPECT_EQ(c.token_file, std::filesystem::path("/etc/fapcast/t.txt"));
  EXPECT_EQ(c.rtp_networks, std::vector<std::string>{"10.0.0.0/8"});
  EXPECT_EQ(c.sentence_bytes, 64u);
  EXPECT_EQ(c.pacer_priority, 20);
  EXPECT_EQ(c.limits.max_queue, 3u);
  const auto rule_of = [](const char* text) {
    ServeConfig d;
    try {
      apply_serve_config(text, "serve.json", ".", d);
    } catch (const InputError& e) {
      return e.rule();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(rule_of(R"({"colour":1})"), "serve-config-key");
  EXPECT_EQ(rule_of(R"({"fps":0})"), "serve-config-value");
  EXPECT_EQ(rule_of(R"({"pacer_priority":100})"), "serve-config-value");  // SCHED_FIFO's range is 1..99
  EXPECT_EQ(rule_of(R"({"pacer_priority":-1})"), "serve-config-value");
  EXPECT_EQ(rule_of(R"({"pacer_priority":"high"})"), "serve-config-value");
  EXPECT_EQ(rule_of(R"({"pacer_priority":0})"), "accepted");
  EXPECT_EQ(rule_of("{\n\"fps\":"), "serve-config-json");
}

TEST(SayRequestTest, PiecesFollowTheFrontEndsCuts) {
  SayRequest r = parse_say_request(R"({"text":"One two. Three four five six. Seven."})", {});
  // "One two. " | "Three four five " (no sentence end within 16 bytes: cut after a space) | "six. Seven."
  EXPECT_EQ(sentence_offsets(r, 16), (std::vector<std::size_t>{0, 9, 25}));
  EXPECT_EQ(sentence_offsets(r), (std::vector<std::size_t>{0}));  // short sentences packed
  // A run of white space longer than a piece gives no blank piece (the synthesiser would refuse it).
  r = parse_say_request(R"({"text":"One two.)" + std::string(40, ' ') + R"(Three."})", {});
  const std::vector<std::size_t> pieces = sentence_offsets(r, 16);
  ASSERT_FALSE(pieces.empty());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const std::size_t end = i + 1 < pieces.size() ? pieces[i + 1] : r.text.size();
    EXPECT_NE(r.text.substr(pieces[i], end - pieces[i]).find_first_not_of(' '), std::string::npos) << "piece " << i;
  }
  EXPECT_NE(r.text.substr(pieces.back()).find("Three."), std::string::npos);
  r = parse_say_request(R"({"ssml":"<speak>One. Two.</speak>","interrupt":true,"srtp":false,"rtp":"udp://127.0.0.1:5004"})", {});
  EXPECT_TRUE(r.ssml);
  EXPECT_TRUE(r.interrupt);
  EXPECT_EQ(r.srtp, false);
  EXPECT_EQ(sentence_offsets(r, 16), (std::vector<std::size_t>{0}));
  try {
    (void)parse_say_request(R"({"text": 5})", {});
    FAIL();
  } catch (const RequestError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.rule(), "field-type");
  }
}

}  // namespace
}  // namespace fapcast
