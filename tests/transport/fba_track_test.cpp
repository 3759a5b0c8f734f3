// The codec bridge: FAP tracks through FBA access units, RTP packets with loss, and back.
#include "fapcast/transport/fba_track.hpp"

#include "fapcast/core/frame_rate.hpp"
#include "fapcast/transport/rtp_streamer.hpp"
#include "fapcast/transport/track_file.hpp"
#include "support/run_command.hpp"
#include "transport/test_seed.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace fapcast {
namespace {

using Clock = RtpStreamReceiver::Clock;

// A SYNTHETIC smooth track: jaw and lip FAPs following slow sines.
FapSequence smooth_track(int n, FrameRate rate) {
  FapSequence seq;
  seq.name = "synthetic";
  seq.rate = rate;
  for (int k = 0; k < n; ++k) {
    FapFrame f;
    f.set(3, static_cast<std::int32_t>(300 * std::sin(k * 0.11)));
    f.set(4, static_cast<std::int32_t>(-80 * std::sin(k * 0.07)));
    f.set(5, static_cast<std::int32_t>(60 * std::cos(k * 0.05)));
    f.set(12, static_cast<std::int32_t>(40 * std::sin(k * 0.2)));
    seq.frames.push_back(f);
  }
  return seq;
}

TEST(FbaTrack, UnitsSitOnTheWavTimelineWithIntraAtThePeriod) {
  const auto seq = smooth_track(100, {30000, 1001});
  FbaEncoderOptions o;
  o.intra_period = 12;
  std::vector<MediaUnit> units;
  ASSERT_FALSE(encode_track_units(seq, SampleRate{44100}, o, units));
  ASSERT_EQ(units.size(), 100u);
  for (std::size_t k = 0; k < units.size(); ++k) {
    EXPECT_EQ(units[k].sample, frame_to_sample(static_cast<std::int64_t>(k), {30000, 1001}, SampleRate{44100}));
    EXPECT_EQ(units[k].intra, k % 12 == 0) << k;
  }
}

struct FbaLossCase {
  double loss;
  FrameRate rate;
  std::int64_t clock;
};
class FbaOverLossyRtp : public testing::TestWithParam<FbaLossCase> {};

// Through RTP packets with random loss (no sockets): every frame the receiver decodes equals the
// sent frame at the same position, and frames in gaps hold the frame before them.
TEST_P(FbaOverLossyRtp, DecodedFramesAreExactAndGapsHold) {
  const auto [loss, rate, clock] = GetParam();
  const std::uint64_t seed = test::test_seed(test::kTransportSeed);
  std::mt19937_64 rng(seed);
  const auto seq = smooth_track(600, rate);
  FbaEncoderOptions o;
  o.fap_quant = 0;
  o.intra_period = 15;
  std::vector<MediaUnit> units;
  ASSERT_FALSE(encode_track_units(seq, SampleRate{clock}, o, units));
  ReceiverOptions ro;
  ro.clock_rate = SampleRate{clock};
  ro.make_validator = make_fba_unit_validator;
  RtpStreamReceiver rx(ro);
  ReceivedTrack track(SampleRate{clock}, 3600);
  RtpStreamIds ids{99, 65000, 4'294'000'000u};
  std::vector<ReceivedUnit> out;
  Clock::time_point now{};
  std::bernoulli_distribution drop(loss);
  std::vector<bool> sent(units.size());
  for (std::size_t i = 0; i < units.size(); ++i) {
    now += std::chrono::milliseconds(1);
    if (i > 1 && drop(rng)) continue;  // frames 0 and 1 arrive: the source is validated at 0
    sent[i] = true;
    std::vector<std::uint8_t> packet;
    ASSERT_FALSE(pack_animation_packet(units[i], i, ids, 96, packet));
    (void)rx.on_datagram(packet, now, out);
  }
  rx.flush(out);
  std::set<std::size_t> decoded;
  for (const auto& u : out) {
    ASSERT_FALSE(track.add(u));
    decoded.insert(static_cast<std::uint16_t>(u.extended_sequence - ids.first_sequence));
  }
  const auto& got = track.sequence();
  EXPECT_EQ(got.rate, rate);
  std::size_t last = 0;
  for (std::size_t i = 0; i < units.size(); ++i)
    if (decoded.contains(i)) last = i;
  ASSERT_EQ(got.frames.size(), last + 1) << "reproduce: FAPCAST_SEED=" << seed;
  for (std::size_t i = 0; i < got.frames.size(); ++i) {
    if (decoded.contains(i)) {
      EXPECT_EQ(got.frames[i], seq.frames[i]) << "frame " << i;
    } else {
      EXPECT_EQ(got.frames[i], got.frames[i - 1]) << "held frame " << i;
    }
  }
  EXPECT_EQ(track.stats().held_frames, got.frames.size() - decoded.size());
  EXPECT_EQ(track.stats().decode_errors, 0u);
}

INSTANTIATE_TEST_SUITE_P(Table, FbaOverLossyRtp,
                         testing::Values(FbaLossCase{0.0, {60, 1}, 48000}, FbaLossCase{0.1, {25, 1}, 48000},
                                         FbaLossCase{0.3, {30000, 1001}, 44100},
                                         FbaLossCase{0.3, {24000, 1001}, 48000}));

TEST(ReceivedTrack, HostileTimestampsCannotGrowTheTrack) {
  const auto seq = smooth_track(50, {60, 1});
  FbaEncoderOptions o;
  o.intra_period = 1;
  std::vector<MediaUnit> units;
  ASSERT_FALSE(encode_track_units(seq, SampleRate{48000}, o, units));
  ReceivedTrack track(SampleRate{48000}, 1.0);  // 60 frames at the stream's 60 fps
  for (std::size_t i = 0; i < units.size(); ++i) {
    ReceivedUnit u;
    u.bytes = units[i].bytes;
    u.intra = true;
    // Pairs 9.9 s apart (each confirms the jump before it would be filled), 6 h between pairs.
    u.timestamp = static_cast<std::uint32_t>((i / 2) * 0x3fffffffull + (i % 2) * 475'000);
    (void)track.add(u);
  }
  EXPECT_LE(track.sequence().frames.size(), 60u);
  EXPECT_TRUE(track.full());
  EXPECT_GT(track.stats().over_limit, 0u);
}

class TrackFileRoundTrip : public testing::TestWithParam<const char*> {};
TEST_P(TrackFileRoundTrip, WritesAndReadsBackTheSameFrames) {
  const auto seq = smooth_track(40, {25, 1});
  const std::string path = test::make_temp_dir("track") + "/t" + GetParam();
  TrackWriteOptions options;
  options.sample_rate = SampleRate{48000};
  const auto notes = write_track_file(path, seq, options);
  const auto back = read_track_file(path);
  EXPECT_EQ(back.frames, seq.frames);
  EXPECT_EQ(back.rate, seq.rate);
  if (std::string(GetParam()) == ".fba") {
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0], "standard FBA at fap_quant 0 (lossless)");
  }
}

// An .fba track file is lossless whatever the values: the standard syntax where it reaches them,
// else the fapcast profile, and the note says which.
TEST(TrackFile, FbaIsLosslessBeyondTheStandardRange) {
  auto seq = smooth_track(40, {25, 1});
  seq.frames[7].set(47, 2955);  // tongue_roll as `say` makes it: beyond +/-1860
  const std::string path = test::make_temp_dir("track") + "/wide.fba";
  const auto notes = write_track_file(path, seq);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("fapcast profile (lossless)"), std::string::npos) << notes[0];
  EXPECT_NE(notes[0].find("frame 7, FAP 47 tongue_roll"), std::string::npos) << notes[0];
  EXPECT_EQ(read_track_file(path).frames, seq.frames);
}
INSTANTIATE_TEST_SUITE_P(Formats, TrackFileRoundTrip, testing::Values(".fap", ".fba", ".json"),
                         [](const auto& info) { return std::string(info.param + 1); });

TEST(TrackFile, UnknownExtensionNamesTheFile) {
  try {
    read_track_file("x.txt");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "x.txt: track-format: expected .fap, .fba or .json");
  }
}

}  // namespace
}  // namespace fapcast
