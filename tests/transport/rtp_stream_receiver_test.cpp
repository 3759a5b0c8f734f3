#include "fapcast/transport/rtp_stream_receiver.hpp"

#include "fapcast/transport/fba_payload.hpp"
#include "fapcast/transport/rtp_error.hpp"
#include "transport/test_seed.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fapcast {
namespace {

using Bytes = std::vector<std::uint8_t>;
using Clock = RtpStreamReceiver::Clock;
using std::chrono::milliseconds;

constexpr std::uint32_t kSsrc = 0xabcdef01;

Bytes packet(std::uint16_t seq, bool intra, std::uint32_t ssrc = kSsrc, std::uint8_t pt = 96) {
  RtpHeader h;
  h.marker = true;
  h.payload_type = pt;
  h.sequence = seq;
  h.timestamp = 1000u + 800u * seq;
  h.ssrc = ssrc;
  Bytes payload;
  pack_fba_payload(intra, false, Bytes{static_cast<std::uint8_t>(seq), static_cast<std::uint8_t>(seq >> 8)}, payload);
  Bytes out;
  EXPECT_FALSE(pack_rtp(h, payload, out));
  return out;
}

// Feeds packets at 1 ms intervals and flushes; returns the delivered sequence numbers (16 bits).
struct Feed {
  RtpStreamReceiver rx;
  std::vector<ReceivedUnit> out;
  Clock::time_point now = Clock::time_point{} + std::chrono::hours(1);
  explicit Feed(ReceiverOptions o = {}) : rx(o) {}
  std::error_code offer(const Bytes& p) {
    now += milliseconds(1);
    return rx.on_datagram(p, now, out);
  }
  std::vector<std::uint16_t> delivered() {
    rx.flush(out);
    std::vector<std::uint16_t> seqs;
    for (const auto& u : out) seqs.push_back(static_cast<std::uint16_t>(u.extended_sequence));
    return seqs;
  }
};

TEST(RtpStreamReceiver, InOrderDeliversEverything) {
  Feed f;
  for (std::uint16_t s = 0; s < 10; ++s) EXPECT_FALSE(f.offer(packet(s, s == 0)));
  EXPECT_EQ(f.delivered(), (std::vector<std::uint16_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(f.rx.stats().lost, 0u);
  EXPECT_EQ(f.rx.stats().delivered, 10u);
  EXPECT_TRUE(f.out[0].after_loss);
  EXPECT_FALSE(f.out[1].after_loss);
  EXPECT_EQ(f.out[3].bytes, (Bytes{3, 0}));
}

TEST(RtpStreamReceiver, ReordersAndDropsDuplicates) {
  Feed f;
  for (const std::uint16_t s : {1, 0, 2, 2, 4, 3, 1, 5}) (void)f.offer(packet(s, s == 0));
  EXPECT_EQ(f.delivered(), (std::vector<std::uint16_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(f.rx.stats().duplicates, 2u);
  EXPECT_EQ(f.rx.stats().lost, 0u);
}

TEST(RtpStreamReceiver, ExtendsSequenceNumbersAcrossTheWrap) {
  Feed f;
  std::uint16_t s = 65530;
  for (int i = 0; i < 12; ++i, ++s) EXPECT_FALSE(f.offer(packet(s, i == 0)));
  const auto seqs = f.delivered();
  ASSERT_EQ(seqs.size(), 12u);
  for (std::size_t i = 1; i < f.out.size(); ++i)
    EXPECT_EQ(f.out[i].extended_sequence, f.out[i - 1].extended_sequence + 1);
  EXPECT_EQ(f.rx.stats().lost, 0u);
}

TEST(RtpStreamReceiver, AfterLossWaitsForTheNextIntraUnit) {
  Feed f;
  // 0 intra, 1, [2 lost], 3, 4, 5 intra, 6
  for (const std::uint16_t s : {0, 1, 3, 4, 5, 6}) (void)f.offer(packet(s, s == 0 || s == 5));
  f.rx.poll(f.now + milliseconds(100), f.out);
  EXPECT_EQ(f.delivered(), (std::vector<std::uint16_t>{0, 1, 5, 6}));
  EXPECT_EQ(f.rx.stats().lost, 1u);
  EXPECT_EQ(f.rx.stats().skipped_waiting_intra, 2u);
  EXPECT_TRUE(f.out[2].after_loss);
  // The lost packet turning up now is late, not delivered.
  EXPECT_EQ(f.offer(packet(2, false)), make_error_code(RtpErrc::kLate));
  EXPECT_EQ(f.rx.stats().late, 1u);
}

TEST(RtpStreamReceiver, ALateJoinerStartsAtAnIntraUnit) {
  Feed f;
  for (std::uint16_t s = 100; s < 110; ++s) (void)f.offer(packet(s, s == 104));
  EXPECT_EQ(f.delivered(), (std::vector<std::uint16_t>{104, 105, 106, 107, 108, 109}));
  EXPECT_EQ(f.rx.stats().lost, 0u);
  EXPECT_EQ(f.rx.stats().skipped_waiting_intra, 4u);
}

TEST(RtpStreamReceiver, AGapIsHeldNoLongerThanTheBufferAllows) {
  ReceiverOptions o;
  o.reorder_capacity = 4;
  o.reorder_delay = milliseconds(1000);
  Feed f(o);
  (void)f.offer(packet(0, true));
  (void)f.offer(packet(1, false));  // a run of two: the source is validated
  for (std::uint16_t s = 3; s < 7; ++s) (void)f.offer(packet(s, s == 6));
  EXPECT_LE(f.rx.held_packets(), 4u);
  EXPECT_EQ(f.rx.stats().lost, 1u);  // the buffer filled: seq 2 declared lost without waiting
  EXPECT_EQ(f.delivered(), (std::vector<std::uint16_t>{0, 1, 6}));
}

TEST(RtpStreamReceiver, LocksOnOneSourceAndOnePayloadType) {
  Feed f;
  EXPECT_FALSE(f.offer(packet(0, true)));
  EXPECT_FALSE(f.rx.locked_ssrc());  // one packet is no run (RFC 3550 A.1 MIN_SEQUENTIAL 2)
  EXPECT_FALSE(f.offer(packet(1, false)));
  EXPECT_EQ(f.rx.locked_ssrc(), kSsrc);
  EXPECT_EQ(f.offer(packet(2, true, kSsrc + 1)), make_error_code(RtpErrc::kForeignSsrc));
  EXPECT_EQ(f.offer(packet(2, true, kSsrc, 97)), make_error_code(RtpErrc::kWrongPayloadType));
  EXPECT_EQ(f.rx.locked_ssrc(), kSsrc);
  ReceiverOptions given;
  given.ssrc = 42;
  Feed g(given);
  EXPECT_EQ(g.offer(packet(0, true)), make_error_code(RtpErrc::kForeignSsrc));
  EXPECT_FALSE(g.offer(packet(0, true, 42)));
}

TEST(RtpStreamReceiver, AJumpNeedsTwoPacketsInARow) {
  Feed f;
  for (std::uint16_t s = 0; s < 5; ++s) (void)f.offer(packet(s, s == 0));
  EXPECT_EQ(f.offer(packet(30000, true)), make_error_code(RtpErrc::kSequenceJump));
  EXPECT_FALSE(f.offer(packet(5, false)));  // the stream goes on undisturbed
  EXPECT_EQ(f.offer(packet(40000, true)), make_error_code(RtpErrc::kSequenceJump));
  EXPECT_FALSE(f.offer(packet(40001, true)));  // confirmed: the sender restarted its numbering
  EXPECT_EQ(f.delivered(), (std::vector<std::uint16_t>{0, 1, 2, 3, 4, 5, 40001}));
  EXPECT_EQ(f.rx.stats().sequence_jumps, 2u);
}

// RFC 3550 A.8: with transit times alternating by 10 ms, |D| is 480 units at 48 kHz every
// packet, and J = J + (|D| - J) / 16 approaches 480 geometrically.
TEST(RtpStreamReceiver, InterarrivalJitterFollowsRfc3550) {
  RtpStreamReceiver rx;
  std::vector<ReceivedUnit> out;
  const Clock::time_point t0{};
  for (std::uint16_t s = 0; s < 200; ++s) {
    const auto arrival = t0 + std::chrono::microseconds(16667 * s) + milliseconds(s % 2 ? 10 : 0);
    RtpHeader h;
    h.sequence = s;
    h.timestamp = 5u + 800u * s;  // 60 fps at 48 kHz
    h.ssrc = 1;
    Bytes p;
    ASSERT_FALSE(pack_rtp(h, Bytes{0x80}, p));
    ASSERT_FALSE(rx.on_datagram(p, arrival, out));
  }
  // Arrival spacing 16.667 ms vs 800 units = 16.6667 ms: the residual is below 1 unit per step.
  EXPECT_NEAR(rx.stats().jitter, 480.0, 2.0);
  EXPECT_NEAR(rx.jitter_seconds(), 0.010, 0.0001);
}

// Hostile input: random bytes and mutated packets never crash, never grow the buffer past its
// bound, and the counters account for every datagram.
TEST(RtpStreamReceiver, HostileDatagramsAreBoundedAndCounted) {
  const std::uint64_t seed = test::test_seed(test::kTransportSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  ReceiverOptions o;
  o.reorder_capacity = 16;
  Feed f(o);
  for (int i = 0; i < 50000; ++i) {
    Bytes p = packet(static_cast<std::uint16_t>(rng()), rng() % 4 == 0, rng() % 8 ? kSsrc : static_cast<std::uint32_t>(rng()));
    const int kind = static_cast<int>(rng() % 4);
    if (kind == 0) p.resize(rng() % p.size());
    if (kind == 1) p[rng() % p.size()] = static_cast<std::uint8_t>(rng());
    if (kind == 2) p.assign(rng() % 64, static_cast<std::uint8_t>(rng()));
    (void)f.offer(p);
    ASSERT_LE(f.rx.held_packets(), 16u);
    if (f.out.size() > 1000) f.out.clear();
  }
  f.rx.flush(f.out);
  const ReceiverStats& s = f.rx.stats();
  EXPECT_EQ(s.datagrams, 50000u);
  EXPECT_EQ(s.datagrams, s.accepted + s.late + s.duplicates + s.malformed + s.foreign_ssrc +
                             s.wrong_payload_type + s.sequence_jumps + s.probation_discarded);
  EXPECT_EQ(f.rx.held_packets(), 0u);
}

}  // namespace
}  // namespace fapcast
