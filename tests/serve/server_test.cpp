// fapcast::Server on loopback (spec/serve.md): who may use it, the bounds, the routes, a say to
// RTP (and SRTP) received by the transport's own receiver, a live WebSocket client in sync,
// barge-in and the queue, and a clean stop. Every test speaks a short text (real time: < 1 s).
#include "serve_support.hpp"

#include "fapcast/core/frame_rate.hpp"
#include "fapcast/serve/live_message.hpp"
#include "fapcast/transport/rtp_packet.hpp"
#include "fapcast/transport/rtp_stream_receiver.hpp"
#include "fapcast/transport/srtp_key.hpp"
#include "fapcast/transport/udp_receiver.hpp"
#include "support/serve_client.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <set>

namespace fapcast::test {
namespace {
using nlohmann::json;

// One server for the tests that need no configuration of their own (each uses its own channel);
// stopped and freed at exit.
TestServer& shared_server() {
  static TestServer server;
  return server;
}

std::uint16_t port() { return shared_server().port(); }

// ---- who may use it ---------------------------------------------------------------------------

TEST(ServeAuth, MissingTokenIs401BeforeTheBodyIsRead) {
  const auto before = get(port(), "/v1/stats").json();
  // Headers that promise a body which never comes: the answer cannot wait for it.
  const Answer a = http_request(port(), http::verb::post, "/v1/say", {}, {{"Content-Type", "application/json"}}, 64);
  EXPECT_EQ(a.status, 401);
  EXPECT_EQ(a.json()["error"], "token-missing");
  EXPECT_EQ(a.response[http::field::www_authenticate], "Bearer realm=\"fapcast\"");
  const auto after = get(port(), "/v1/stats").json();
  EXPECT_EQ(after["unauthorized"].get<int>(), before["unauthorized"].get<int>() + 1);
  EXPECT_EQ(after["sessions_started"], before["sessions_started"]);
}

TEST(ServeAuth, WrongTokenIs401OnEveryPathEvenUnknownOnes) {
  for (const char* target : {"/v1/stats", "/", "/no/such/path", "/three/three.module.js"}) {
    const Answer a = http_request(port(), http::verb::get, target, {}, {{"Authorization", "Bearer not-the-token-at-all"}});
    EXPECT_EQ(a.status, 401) << target;
    EXPECT_EQ(a.json()["error"], "token-wrong") << target;
  }
  // A prefix of the token is not the token.
  const Answer prefix = http_request(port(), http::verb::get, "/v1/stats", {},
                                     {{"Authorization", "Bearer " + std::string(kToken).substr(0, 20)}});
  EXPECT_EQ(prefix.status, 401);
}

TEST(ServeAuth, TokenAsQueryParameterOnGetAndRedactedInTheLog) {
  const Answer a = http_request(port(), http::verb::get, std::string("/?token=") + kToken, {}, {});
  EXPECT_EQ(a.status, 200);
  EXPECT_NE(a.body.find("<html"), std::string::npos);
  const Answer js = http_request(port(), http::verb::get, std::string("/three/examples/loader.js?token=") + kToken, {}, {});
  EXPECT_EQ(js.status, 200);
  EXPECT_EQ(js.body, "// a loader\n");
  // A symbolic link is served under its own path too (GLTFLoader imports build/three.module.js).
  const Answer linked = http_request(port(), http::verb::get, std::string("/three/build/three.module.js?token=") + kToken, {}, {});
  EXPECT_EQ(linked.status, 200);
  EXPECT_EQ(linked.body, "export const REVISION = 'test';\n");
  for (const std::string& line : shared_server().log_lines()) EXPECT_EQ(line.find(kToken), std::string::npos) << line;
  // Not on a POST: a form could carry it there.
  const Answer p = http_request(port(), http::verb::post, std::string("/v1/say?token=") + kToken, "{\"text\":\"hi\"}", {});
  EXPECT_EQ(p.status, 401);
  // An empty ?token= presents no token (found by serve_http_request_fuzz: seed empty-query-token).
  const Answer empty = http_request(port(), http::verb::get, "/three/examples/loader.js?token=&x", {}, {});
  EXPECT_EQ(empty.status, 401);
  EXPECT_EQ(empty.json()["error"], "token-missing");
}

// The answer to a WebSocket handshake as a plain HTTP exchange (Boost 1.74's handshake does not
// hand out the answer of a declined upgrade).
Answer websocket_handshake(std::uint16_t port, const std::string& target, Headers headers) {
  headers.emplace_back("Upgrade", "websocket");
  headers.emplace_back("Connection", "Upgrade");
  headers.emplace_back("Sec-WebSocket-Key", "dGhlIHNhbXBsZSBub25jZQ==");
  headers.emplace_back("Sec-WebSocket-Version", "13");
  return http_request(port, http::verb::get, target, {}, headers);
}

TEST(ServeAuth, WrongOriginIs403ForPostAndWebSocket) {
  const Answer a = http_request(port(), http::verb::post, "/v1/say", R"({"text":"Hi.","channel":"origin"})",
                                {{"Authorization", std::string("Bearer ") + kToken}, {"Origin", "http://evil.example"}});
  EXPECT_EQ(a.status, 403);
  EXPECT_EQ(a.json()["error"], "origin-forbidden");
  EXPECT_THROW(LiveTestClient(port(), "/v1/live?channel=origin",
                              {{"Authorization", std::string("Bearer ") + kToken}, {"Origin", "http://evil.example"}}),
               beast::system_error);
  const Answer ws = websocket_handshake(port(), "/v1/live?channel=origin",
                                        {{"Authorization", std::string("Bearer ") + kToken}, {"Origin", "http://evil.example"}});
  EXPECT_EQ(ws.status, 403);
  EXPECT_EQ(ws.json()["error"], "origin-forbidden");
  // The server's own Origin passes (the page on it).
  const Answer own = http_request(port(), http::verb::get, "/v1/stats", {},
                                  {{"Authorization", std::string("Bearer ") + kToken},
                                   {"Origin", "http://127.0.0.1:" + std::to_string(port())}});
  EXPECT_EQ(own.status, 200);
}

TEST(ServeAuth, WebSocketWithoutTokenRefused) {
  EXPECT_THROW(LiveTestClient(port(), "/v1/live", {}), beast::system_error);
  const Answer ws = websocket_handshake(port(), "/v1/live", {});
  EXPECT_EQ(ws.status, 401);
  EXPECT_EQ(ws.json()["error"], "token-missing");
  // The same handshake with the token is an upgrade: the refusal above was the token's.
  EXPECT_EQ(websocket_handshake(port(), "/v1/live?channel=handshake", {{"Authorization", std::string("Bearer ") + kToken}}).status, 101);
  // The browser's way: the token as a subprotocol beside fapcast.v1.
  LiveTestClient c(port(), "/v1/live?channel=subproto",
                   {{"Sec-WebSocket-Protocol", std::string("fapcast.v1, bearer.") + kToken}});
  EXPECT_TRUE(c.ws.is_open());
}

// ---- bad requests and bounds ------------------------------------------------------------------

TEST(ServeBadRequest, MalformedJsonNamesTheByte) {
  const Answer a = post(port(), "/v1/say", R"({"text":"hi",})");
  EXPECT_EQ(a.status, 400);
  EXPECT_EQ(a.json()["error"], "json-malformed");
  EXPECT_EQ(a.json()["detail"].get<std::string>().rfind("byte 13:", 0), 0u) << a.body;
}

TEST(ServeBadRequest, HugeBodyIs413FromItsContentLength) {
  const Answer a = http_request(port(), http::verb::post, "/v1/say", {},
                                {{"Authorization", std::string("Bearer ") + kToken}}, 1 << 20);
  EXPECT_EQ(a.status, 413);
  EXPECT_EQ(a.json()["error"], "body-too-large");
}

TEST(ServeBadRequest, TextTooLongIs413) {
  const Answer a = post(port(), "/v1/say", json{{"text", std::string(5000, 'a')}}.dump());
  EXPECT_EQ(a.status, 413);
  EXPECT_EQ(a.json()["error"], "text-too-long");
}

TEST(ServeBadRequest, UnknownRouteIs404AndWrongMethod405) {
  EXPECT_EQ(get(port(), "/v1/nothing").status, 404);
  EXPECT_EQ(get(port(), "/v1/sessions/0123456789abcdef").json()["error"], "session-unknown");
  EXPECT_EQ(get(port(), "/three/../token").status, 404);
  EXPECT_EQ(get(port(), "/v1/say").status, 405);
}

TEST(ServeBadRequest, FieldsCheckedOneByOne) {
  EXPECT_EQ(post(port(), "/v1/say", R"({"text":"hi","colour":"red"})").json()["error"], "unknown-field");
  EXPECT_EQ(post(port(), "/v1/say", R"({"text":"hi","ssml":"<speak>hi</speak>"})").json()["error"], "text-twice");
  EXPECT_EQ(post(port(), "/v1/say", R"({"text":"   "})").json()["error"], "text-empty");
  EXPECT_EQ(post(port(), "/v1/say", R"({"text":"hi","voice":"nobody"})").json()["error"], "voice-unknown");
  EXPECT_EQ(post(port(), "/v1/say", R"({"text":"hi","lang":"xx-none"})").json()["error"], "lang-unsupported");
  EXPECT_EQ(post(port(), "/v1/say", R"({"text":"hi","rtp":"udp://example.org:5004"})").json()["error"], "rtp-url");
  EXPECT_EQ(post(port(), "/v1/say", R"({"text":"hi","rtp":"udp://127.0.0.1:5004","srtp":true})").json()["error"],
            "srtp-unavailable");
}

TEST(ServeBadRequest, RtpToADisallowedNetworkIs403) {
  const Answer a = post(port(), "/v1/say", R"({"text":"Hi.","rtp":"udp://10.1.2.3:5004","channel":"rtpnet"})");
  EXPECT_EQ(a.status, 403);
  EXPECT_EQ(a.json()["error"], "rtp-forbidden");
  const Answer mc = post(port(), "/v1/say", R"({"text":"Hi.","rtp":"udp://239.1.2.3:5004","channel":"rtpnet"})");
  EXPECT_EQ(mc.status, 403);  // multicast only when configured
}

// ---- the routes -------------------------------------------------------------------------------

TEST(ServeRoutes, FaceIsABinaryGltfWithMorphTargets) {
  const Answer a = get(port(), "/v1/face.glb");
  ASSERT_EQ(a.status, 200);
  EXPECT_EQ(a.response[http::field::content_type], "model/gltf-binary");
  ASSERT_GT(a.body.size(), 20u);
  EXPECT_EQ(a.body.substr(0, 4), "glTF");
  // The JSON chunk names the morph targets: the k components and the six expressions.
  const std::uint32_t json_length = static_cast<std::uint8_t>(a.body[12]) | static_cast<std::uint8_t>(a.body[13]) << 8 |
                                    static_cast<std::uint8_t>(a.body[14]) << 16 | static_cast<std::uint32_t>(static_cast<std::uint8_t>(a.body[15])) << 24;
  const json gltf = json::parse(a.body.substr(20, json_length));
  const auto& targets = gltf["meshes"][0]["primitives"][0]["targets"];
  EXPECT_GT(targets.size(), 6u);
  EXPECT_EQ(get(port(), "/v1/face.glb?voice=nobody").status, 404);
}

TEST(ServeRoutes, StatsCountRequests) {
  const auto a = get(port(), "/v1/stats").json();
  const auto b = get(port(), "/v1/stats").json();
  EXPECT_GE(b["requests"].get<int>(), a["requests"].get<int>() + 1);
}

// ---- RTP --------------------------------------------------------------------------------------

struct RtpPair {
  asio::io_context io, io2;  // before the receivers that use them
  std::unique_ptr<UdpReceiver> animation, audio;
  RtpStreamReceiver animation_stream, audio_stream;
  std::vector<ReceivedUnit> animation_units, audio_units;
  std::thread a_thread, b_thread;

  explicit RtpPair(std::optional<SrtpMasterKey> key)
      : animation_stream(ReceiverOptions{}),
        audio_stream([] {
          ReceiverOptions o;
          o.payload_type = kDefaultL16PayloadType;
          o.fba_payload = false;
          return o;
        }()) {
    ReceiverSocketOptions s;
    s.srtp = key;
    for (int attempt = 0; attempt < 20 && !audio; ++attempt) {
      animation = std::make_unique<UdpReceiver>(io, udp::endpoint(asio::ip::make_address("127.0.0.1"), 0), s);
      std::error_code ec;
      const auto p = static_cast<std::uint16_t>(animation->local_endpoint().port() + 2);
      audio = std::make_unique<UdpReceiver>(io2, udp::endpoint(asio::ip::make_address("127.0.0.1"), p), s, ec);
      if (ec) audio.reset();
    }
  }
  std::uint16_t port() const { return animation->local_endpoint().port(); }
  void start(std::chrono::milliseconds idle = std::chrono::milliseconds(3000)) {
    ReceiveLimits l;
    l.idle_timeout = idle;
    l.max_duration = std::chrono::seconds(10);
    a_thread = std::thread([this, l] { animation->run(animation_stream, l, [this](ReceivedUnit&& u) { animation_units.push_back(std::move(u)); }); });
    b_thread = std::thread([this, l] { audio->run(audio_stream, l, [this](ReceivedUnit&& u) { audio_units.push_back(std::move(u)); }); });
  }
  void join() {
    if (a_thread.joinable()) a_thread.join();
    if (b_thread.joinable()) b_thread.join();
  }
  ~RtpPair() { join(); }
};

void expect_rtp_session(TestServer& server, RtpPair& rtp, const std::string& body) {
  ASSERT_TRUE(rtp.audio);
  rtp.start();
  const Answer a = post(server.port(), "/v1/say", body);
  ASSERT_EQ(a.status, 202) << a.body;
  EXPECT_EQ(a.json()["state"], "speaking");
  rtp.join();  // each ends on the session's BYE
  const json status = get(server.port(), "/v1/sessions/" + a.json()["session"].get<std::string>()).json();
  EXPECT_EQ(status["state"], "done") << status.dump();
  ASSERT_GT(status["frames_sent"].get<int>(), 5);
  EXPECT_EQ(rtp.animation_units.size(), status["frames_sent"].get<std::size_t>());
  EXPECT_GT(rtp.audio_units.size(), 10u);
  EXPECT_GE(rtp.animation_stream.stats().sender_reports, 1u);
  EXPECT_GE(rtp.audio_stream.stats().sender_reports, 1u);
  EXPECT_EQ(rtp.animation_stream.stats().byes, 1u);
  // The L16 audio: 2 bytes a sample, and samples that are not all silence.
  std::size_t loud = 0;
  for (const ReceivedUnit& u : rtp.audio_units)
    for (std::size_t i = 0; i + 1 < u.bytes.size(); i += 2)
      loud += std::abs(static_cast<std::int16_t>(u.bytes[i] << 8 | u.bytes[i + 1])) > 500;
  EXPECT_GT(loud, 100u);
}

TEST(ServeRtp, SayToRtpIsReceivedWithSenderReports) {
  RtpPair rtp(std::nullopt);
  expect_rtp_session(shared_server(), rtp,
                     json{{"text", "Hello."}, {"channel", "rtp"}, {"rtp", "udp://127.0.0.1:" + std::to_string(rtp.port())}}.dump());
}

TEST(ServeRtp, SrtpWithTheServersKeyIsDecrypted) {
  const SrtpMasterKey key = random_srtp_key();
  write_file_atomically(serve_test_dir() / "srtp.key", srtp_key_text(key) + "\n");
  ServeConfig c = test_config();
  c.srtp_key_file = serve_test_dir() / "srtp.key";
  TestServer server(c);
  RtpPair rtp(key);
  // A second destination whose receiver has no key: it sees the datagrams but no unit.
  RtpPair keyless(std::nullopt);
  ASSERT_TRUE(keyless.audio);
  keyless.start(std::chrono::milliseconds(1500));
  expect_rtp_session(server, rtp,
                     json{{"text", "Hello."},
                          {"rtp", {"udp://127.0.0.1:" + std::to_string(rtp.port()), "udp://127.0.0.1:" + std::to_string(keyless.port())}}}
                         .dump());
  ASSERT_NE(rtp.animation->srtp_stats(), nullptr);
  const SrtpStats& srtp = *rtp.animation->srtp_stats();
  // Every RTP datagram was authenticated before the parser saw it (SRTCP counts there too).
  EXPECT_GE(srtp.unprotected_packets, rtp.animation_stream.stats().datagrams);
  EXPECT_GT(srtp.unprotected_packets, 5u);
  EXPECT_EQ(srtp.auth_failed, 0u);
  EXPECT_EQ(srtp.malformed, 0u);
  keyless.join();
  // Without the key the headers parse (SRTP leaves them in the clear) but no payload is the
  // session's: every one is ciphertext.
  EXPECT_GT(keyless.animation_stream.stats().datagrams, 5u);
  std::set<std::vector<std::uint8_t>> clear;
  for (const ReceivedUnit& u : rtp.animation_units) clear.insert(u.bytes);
  for (const ReceivedUnit& u : rtp.audio_units) clear.insert(u.bytes);
  std::size_t readable = 0;
  for (const ReceivedUnit& u : keyless.animation_units) readable += clear.contains(u.bytes);
  for (const ReceivedUnit& u : keyless.audio_units) readable += clear.contains(u.bytes);
  EXPECT_EQ(readable, 0u);
}

// Every SSRC under the key is drawn once (RFC 3711 section 9.1), so the server keeps them: at most
// limits.max_srtp_streams, two per destination; beyond, SRTP is refused by name (503) while
// plain RTP and live clients go on.
TEST(ServeRtp, TheSrtpKeyServesItsStreamLimitThenRefusesByName) {
  write_file_atomically(serve_test_dir() / "srtp-limit.key", srtp_key_text(random_srtp_key()) + "\n");
  ServeConfig c = test_config();
  c.srtp_key_file = serve_test_dir() / "srtp-limit.key";
  c.limits.max_srtp_streams = 4;
  TestServer server(c);
  RtpPorts sink;
  const auto say = [&](const std::string& channel, std::optional<bool> srtp) {
    json body{{"text", "Hi."}, {"channel", channel}, {"rtp", sink.url()}};
    if (srtp) body["srtp"] = *srtp;
    return post(server.port(), "/v1/say", body.dump());
  };
  EXPECT_EQ(say("a", std::nullopt).status, 202);  // streams 1 and 2 (animation, audio)
  EXPECT_EQ(say("b", true).status, 202);          // 3 and 4
  const Answer refused = say("c", std::nullopt);
  EXPECT_EQ(refused.status, 503) << refused.body;
  EXPECT_EQ(refused.json()["error"], "srtp-streams-exhausted");
  EXPECT_NE(refused.json()["detail"].get<std::string>().find("has served 4 of the 4 streams"), std::string::npos)
      << refused.body;
  EXPECT_EQ(say("d", false).status, 202);  // plain RTP is not under the key
  EXPECT_EQ(post(server.port(), "/v1/say", json{{"text", "Hi."}, {"channel", "e"}}.dump()).status, 202);
  EXPECT_EQ(get(server.port(), "/v1/stats").json()["over_limits"], 1);
}

TEST(ServeRtp, ADestinationThatCannotBeSentToIsDroppedAndTheOthersGoOn) {
  ServeConfig c = test_config();
  c.rtp_networks = {"127.0.0.0/8", "255.255.255.255/32"};
  TestServer server(c);
  RtpPair rtp(std::nullopt);
  // A datagram to the limited broadcast address without SO_BROADCAST fails (EACCES).
  expect_rtp_session(server, rtp,
                     json{{"text", "Hello."},
                          {"rtp", {"udp://255.255.255.255:5004", "udp://127.0.0.1:" + std::to_string(rtp.port())}}}
                         .dump());
  const json stats = get(server.port(), "/v1/stats").json();
  EXPECT_EQ(stats["rtp_destinations_dropped"], 1);
  EXPECT_EQ(stats["sessions_failed"], 0);
}

// ---- live clients -----------------------------------------------------------------------------

TEST(ServeLive, ClientGetsSessionSentenceFramesEndInOrderWithAudioInSync) {
  ServeConfig c = test_config();
  c.sentence_bytes = 16;  // "Hello there. " and "Bye now." are two pieces
  TestServer server(c);
  const auto port = [&] { return server.port(); };
  LiveTestClient client(port(), "/v1/live?channel=live1");
  ASSERT_TRUE(wait_for_stats(port(), [](const json& s) { return s["clients"].get<int>() >= 1; }));
  const Answer a = post(port(), "/v1/say", R"({"text":"Hello there. Bye now.","channel":"live1"})");
  ASSERT_EQ(a.status, 202) << a.body;
  beast::error_code ec;
  auto m = client.read(ec);
  ASSERT_FALSE(ec);
  ASSERT_TRUE(m.text);
  const json session = json::parse(m.bytes);
  EXPECT_EQ(session["type"], "session");
  const auto rate = SampleRate{session["sample_rate"].get<std::int64_t>()};
  const auto components = session["components"].get<std::size_t>();
  const auto number = session["session"].get<std::uint32_t>();
  std::int64_t sentence_start = 0, sentence_samples = 0, audio_in_sentence = 0;
  std::size_t frames = 0, sentence_frames = 0, sentences = 0, in_sentence = 0;
  std::string end_reason;
  for (;;) {
    m = client.read(ec);
    ASSERT_FALSE(ec) << ec.message();
    if (m.text) {
      const json j = json::parse(m.bytes);
      if (j["type"] == "sentence") {
        if (sentences > 0) {
          EXPECT_EQ(in_sentence, sentence_frames);
          EXPECT_EQ(audio_in_sentence, sentence_samples);
          // The next piece starts where this one's audio ends, or later if it was late.
          EXPECT_GE(j["sample"].get<std::int64_t>(), sentence_start + sentence_samples);
        }
        EXPECT_EQ(j["index"].get<std::size_t>(), sentences);
        ++sentences;
        sentence_start = j["sample"];
        sentence_samples = j["samples"];
        sentence_frames = j["frames"];
        EXPECT_FALSE(j["phones"].empty());
        in_sentence = 0;
        audio_in_sentence = 0;
        continue;
      }
      ASSERT_EQ(j["type"], "end");
      end_reason = j["reason"];
      break;
    }
    LiveFrame f;
    ASSERT_FALSE(decode_live_frame(std::span(reinterpret_cast<const std::uint8_t*>(m.bytes.data()), m.bytes.size()), f));
    EXPECT_EQ(f.session, number);
    EXPECT_EQ(f.index, frames);
    EXPECT_EQ(f.weights.size(), components);
    EXPECT_EQ(f.first_of_sentence, in_sentence == 0);
    // Frame j of a sentence starts at its sample and carries the audio up to the next one's.
    const std::int64_t here = frame_to_sample(static_cast<std::int64_t>(in_sentence), FrameRate{25, 1}, rate);
    EXPECT_EQ(f.sample, sentence_start + here);
    const std::int64_t next = in_sentence + 1 < sentence_frames
                                  ? frame_to_sample(static_cast<std::int64_t>(in_sentence + 1), FrameRate{25, 1}, rate)
                                  : sentence_samples;
    EXPECT_EQ(static_cast<std::int64_t>(f.audio.size()), next - here);
    audio_in_sentence += static_cast<std::int64_t>(f.audio.size());
    ++frames;
    ++in_sentence;
  }
  EXPECT_EQ(end_reason, "done");
  EXPECT_EQ(sentences, 2u);
  EXPECT_EQ(session["sentences"], 2);
  EXPECT_EQ(in_sentence, sentence_frames);
  EXPECT_EQ(audio_in_sentence, sentence_samples);
  EXPECT_GT(frames, 5u);
}

TEST(ServeLive, SlowClientIsDroppedWithAReason) {
  ServeConfig c = test_config();
  c.limits.client_queue_frames = 2;
  c.limits.client_send_buffer_bytes = 4096;
  TestServer server(c);
  // A client that does not read, with a receive window of a few KiB: the server's writes stall,
  // its queue of 2 fills within a second of frames (about 2 KiB each).
  asio::io_context ioc;
  websocket::stream<tcp::socket> ws(ioc);
  ws.next_layer().open(tcp::v4());
  ws.next_layer().set_option(asio::socket_base::receive_buffer_size(2048));
  ws.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server.port()));
  ws.set_option(websocket::stream_base::decorator(
      [](websocket::request_type& req) { req.set(http::field::authorization, std::string("Bearer ") + kToken); }));
  ws.handshake("127.0.0.1", "/v1/live");
  ASSERT_TRUE(wait_for_stats(server.port(), [](const json& s) { return s["clients"].get<int>() >= 1; }));
  const Answer a = post(server.port(), "/v1/say", R"({"text":"Hello there, how are you today? I am fine, thank you."})");
  ASSERT_EQ(a.status, 202);
  EXPECT_TRUE(wait_for_stats(server.port(), [](const json& s) { return s["clients_dropped_slow"].get<int>() == 1; }));
  EXPECT_TRUE(wait_for_stats(server.port(), [](const json& s) { return s["clients"].get<int>() == 0; }));
  const std::vector<std::string> lines = server.log_lines();
  const bool dropped = std::any_of(lines.begin(), lines.end(), [](const std::string& l) {
    return l.find("closed: slow-client: 2 messages waiting (limit 2)") != std::string::npos;
  });
  EXPECT_TRUE(dropped);
}

// ---- barge-in and the queue -------------------------------------------------------------------

TEST(ServeQueue, StopEndsASessionAndTheNextQueuedOneStarts) {
  const Answer first = post(port(), "/v1/say", R"({"text":"This is the first thing said, and it goes on for a while.","channel":"q1"})");
  ASSERT_EQ(first.status, 202);
  const Answer second = post(port(), "/v1/say", R"({"text":"Second.","channel":"q1"})");
  ASSERT_EQ(second.status, 202);
  EXPECT_EQ(second.json()["state"], "queued");
  const std::string id1 = first.json()["session"], id2 = second.json()["session"];
  const Answer stopped = post(port(), "/v1/sessions/" + id1 + "/stop", "");
  ASSERT_EQ(stopped.status, 200);
  EXPECT_EQ(stopped.json()["state"], "stopped");
  EXPECT_EQ(stopped.json()["reason"], "stopped");
  const auto state2 = [&] { return get(port(), "/v1/sessions/" + id2).json()["state"].get<std::string>(); };
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (state2() == "queued" || state2() == "starting") {
    ASSERT_LT(std::chrono::steady_clock::now(), until);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(state2() == "speaking" || state2() == "done");
  // Barge-in: "interrupt" stops what speaks and drops the queue.
  const Answer third = post(port(), "/v1/say", R"({"text":"Third, a longer one that would take its time.","channel":"q1"})");
  const Answer fourth = post(port(), "/v1/say", R"({"text":"Fourth.","channel":"q1"})");
  const Answer barge = post(port(), "/v1/say", R"({"text":"Now.","channel":"q1","interrupt":true})");
  ASSERT_EQ(barge.status, 202) << barge.body;
  EXPECT_EQ(barge.json()["state"], "speaking");
  const std::string id3 = third.json()["session"], id4 = fourth.json()["session"];
  for (const std::string& id : {id3, id4}) {
    const json s = get(port(), "/v1/sessions/" + id).json();
    if (id == id3 && s["state"] == "done") continue;  // it may have ended on its own
    EXPECT_EQ(s["state"], "stopped") << s.dump();
    EXPECT_EQ(s["reason"], "interrupted");
  }
}

TEST(ServeQueue, QueueFullIs429) {
  ServeConfig c = test_config();
  c.limits.max_queue = 1;
  TestServer server(c);
  ASSERT_EQ(post(server.port(), "/v1/say", R"({"text":"One, speaking for a little while now."})").status, 202);
  ASSERT_EQ(post(server.port(), "/v1/say", R"({"text":"Two."})").status, 202);
  const Answer three = post(server.port(), "/v1/say", R"({"text":"Three."})");
  EXPECT_EQ(three.status, 429);
  EXPECT_EQ(three.json()["error"], "queue-full");
}

// ---- stop -------------------------------------------------------------------------------------

TEST(ServeStop, StopEndsSessionsAndClientsAndReturns) {
  TestServer server;
  LiveTestClient client(server.port(), "/v1/live");
  ASSERT_TRUE(wait_for_stats(server.port(), [](const json& s) { return s["clients"].get<int>() >= 1; }));
  const Answer a = post(server.port(), "/v1/say", R"({"text":"This sentence will not be finished, because the server stops."})");
  ASSERT_EQ(a.status, 202);
  // The client reads on while the server stops (it answers the close frame).
  beast::error_code ec;
  std::string last_text;
  std::thread reader([&] {
    while (!ec) {
      auto m = client.read(ec);
      if (!ec && m.text) last_text = m.bytes;
    }
  });
  const auto took = server.stop();
  reader.join();
  EXPECT_LT(took, std::chrono::milliseconds(900));  // under the 1 s after which unfinished clients are cut off
  EXPECT_EQ(ec, websocket::error::closed);
  EXPECT_EQ(client.ws.reason().code, websocket::close_code::going_away);
  EXPECT_EQ(json::parse(last_text)["reason"], "shutdown");
  const ServeStats s = server.server->stats();
  EXPECT_EQ(s.sessions_stopped, 1u);
}

}  // namespace
}  // namespace fapcast::test
