// .fap written for each real player, read back the way that player reads it
// (tests/codec/player_readers.hpp, from the facts in spec/fap-text.md "Players"); the default
// strict output read alike by all three wherever the format allows, and a note where it cannot;
// real players' own numbering (1..N under a count of N) read as they play it.
#include "codec/player_readers.hpp"
#include "fapcast/codec/fap_text.hpp"
#include "fapcast/core/input_error.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fapcast {
namespace {

using test::PlayerFrame;
using test::PlayerRead;

enum class Reading { kXface, kOneField };  // what FAP 1/2 mean to the player

// What a player is meant to see in `seq`: every masked FAP's values; FAP 1 and FAP 2 as all their
// fields (Xface) or their one field (Greta, VREng: viseme_select1, expression_select1).
std::vector<PlayerFrame> intended(const FapSequence& seq, Reading reading) {
  std::vector<PlayerFrame> out;
  for (const FapFrame& f : seq.frames) {
    PlayerFrame p;
    if (f.mask.test(1)) {
      const VisemeField& v = f.viseme;
      p.faps[1] = reading == Reading::kXface ? std::vector<double>{double(v.select1), double(v.select2), double(v.blend), double(v.def)}
                                             : std::vector<double>{double(v.select1)};
    }
    if (f.mask.test(2)) {
      const ExpressionField& e = f.expression;
      p.faps[2] = reading == Reading::kXface
                      ? std::vector<double>{double(e.select1), double(e.intensity1), double(e.select2), double(e.intensity2),
                                            double(e.init_face), double(e.def)}
                      : std::vector<double>{double(e.select1)};
    }
    for (int n = 3; n <= kFapCount; ++n)
      if (f.mask.test(n)) p.faps[n] = {double(f.value(n))};
    out.push_back(p);
  }
  return out;
}

// A track as `say --viseme --expression` makes them: FAP 1 (a viseme at full weight or blended),
// FAP 2, lips and jaw, negative values; at `rate`.
FapSequence speech_like(std::mt19937_64& rng, bool fap12, FrameRate rate = {25, 1}) {
  FapSequence seq{"speech like", rate, {}};
  for (int k = 0; k < 40; ++k) {
    FapFrame f;
    for (const int n : {3, 4, 5, 6, 7, 12, 13, 19, 20, 47, 48}) f.set(n, static_cast<std::int32_t>(rng() % 4001) - 2000);
    if (fap12) {
      f.mask.set(1).set(2);
      f.viseme = {static_cast<std::uint8_t>(rng() % 15), static_cast<std::uint8_t>(rng() % 15),
                  static_cast<std::uint8_t>(rng() % 64), rng() % 2 == 0};
      f.expression = {static_cast<std::uint8_t>(rng() % 7), static_cast<std::uint8_t>(rng() % 64), 0, 0, false, false};
    }
    seq.frames.push_back(f);
  }
  return seq;
}

FapTextWriteOptions for_player(FapPlayer p) {
  FapTextWriteOptions o;
  o.player = p;
  return o;
}

TEST(FapPlayers, EachPlayerReadsItsOwnFileAsIntended) {
  std::mt19937_64 rng(20261123);
  for (const bool fap12 : {false, true}) {
    const FapSequence seq = speech_like(rng, fap12);
    const std::string xface = write_fap_text(seq, for_player(FapPlayer::kXface));
    const PlayerRead x = test::xface_read(xface);
    EXPECT_EQ(x.fps, 25);
    EXPECT_EQ(x.frames, intended(seq, Reading::kXface));
    for (const FapPlayer p : {FapPlayer::kGreta, FapPlayer::kVreng}) {
      SCOPED_TRACE(fap_player_name(p));
      const std::string text = write_fap_text(seq, for_player(p));
      EXPECT_EQ(test::greta_read(text).frames, intended(seq, Reading::kOneField));
      EXPECT_EQ(test::vreng_read(text).frames, intended(seq, Reading::kOneField));
      // fapcast reads what it wrote: one integer each for FAP 1/2 in 68-token masks.
      const FapTextRead back = read_fap_text(text, "back.fap");
      EXPECT_TRUE(back.info.single_fap12 || !fap12);
      ASSERT_EQ(back.sequence.frames.size(), seq.frames.size());
      for (std::size_t k = 0; k < seq.frames.size(); ++k) EXPECT_EQ(back.sequence.frames[k], as_mask69(seq.frames[k]));
    }
  }
}

// Xface reads the fps as a whole number: its writer refuses any other rather than have it
// played at the wrong speed; the default writer says so.
TEST(FapPlayers, XfaceNeedsAWholeFrameRate) {
  std::mt19937_64 rng(1);
  const FapSequence ntsc = speech_like(rng, false, {30000, 1001});
  try {
    write_fap_text(ntsc, for_player(FapPlayer::kXface));
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, 11), "player-fps:") << e.what();
  }
  EXPECT_EQ(test::xface_read(write_fap_text(ntsc)).fps, 29);  // what it would do
  const auto notes = fap_text_player_notes(ntsc, {});
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("Xface would play at 29 fps"), std::string::npos) << notes[0];
}

// The default (strict) output: all three read it as intended when FAP 1/2 are absent and the rate
// is whole; with FAP 1/2, Greta and VREng misread it, and the writer's note says so.
TEST(FapPlayers, TheDefaultIsReadAlikeWhereTheFormatAllowsAndSaysSoWhereItCannot) {
  std::mt19937_64 rng(2);
  const FapSequence plain = speech_like(rng, false);
  const std::string text = write_fap_text(plain);
  EXPECT_EQ(test::xface_read(text).frames, intended(plain, Reading::kXface));
  EXPECT_EQ(test::greta_read(text).frames, intended(plain, Reading::kOneField));
  EXPECT_EQ(test::vreng_read(text).frames, intended(plain, Reading::kOneField));
  EXPECT_TRUE(fap_text_player_notes(plain, {}).empty());
  const FapSequence visemes = speech_like(rng, true);
  const std::string strict = write_fap_text(visemes);
  EXPECT_EQ(test::xface_read(strict).frames, intended(visemes, Reading::kXface));
  EXPECT_NE(test::greta_read(strict).frames, intended(visemes, Reading::kOneField));
  EXPECT_NE(test::vreng_read(strict).frames, intended(visemes, Reading::kOneField));
  const auto notes = fap_text_player_notes(visemes, {});
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("--player greta or --player vreng"), std::string::npos) << notes[0];
  // A file for Greta or VREng says what it drops, if anything.
  const auto dropped = fap_text_player_notes(visemes, for_player(FapPlayer::kVreng));
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_NE(dropped[0].find("frames lose"), std::string::npos) << dropped[0];
}

// What real players are known to trip on, checked on the readers themselves (so that the tests
// above mean what they say): Xface and a 69-token mask or a row past its frames; Greta and a
// comment or a decimal; VREng and a tab in the header or a stray CR.
TEST(FapPlayers, TheReadersTripWhereThePlayersDo) {
  const std::string ok = "2.1 x 25 2\n" + std::string(67 * 2, ' ') + "\n";
  (void)ok;
  std::string mask68(2 * 68 - 1, ' ');
  for (int i = 0; i < 68; ++i) mask68[static_cast<std::size_t>(2 * i)] = i == 2 ? '1' : '0';
  const std::string file = "2.1 x 25 2\n" + mask68 + "\n0 10\n" + mask68 + "\n1 20\n";
  EXPECT_EQ(test::xface_read(file).frames.size(), 2u);
  EXPECT_THROW(test::xface_read("2.1 x 25 2\n0 " + mask68 + "\n0 10\n"), test::PlayerCrash);  // 69 tokens
  EXPECT_THROW(test::xface_read("2.1 x 25 2\n" + mask68 + "\n2 10\n"), test::PlayerCrash);    // row 2 of 2
  EXPECT_EQ(test::greta_read("2.1 x 25 2\n# c\n" + mask68 + "\n0 10\n").frames.front().faps.count(3), 0u);
  EXPECT_TRUE(test::greta_read("2.1 x 25 1\n" + mask68 + "\n0 1.5\n").frames.empty());
  EXPECT_THROW(test::vreng_read("2.1\tx 25 1\n" + mask68 + "\n0 10\n"), test::PlayerCrash);
  EXPECT_EQ(test::vreng_read("2.1 x 25 1\n" + mask68 + " \r\n0 10\n").frames.size(), 1u);
  EXPECT_EQ(test::vreng_read("2.0 x 25 1\n" + mask68 + "\n0 10\n").frames[0].faps.at(3), std::vector<double>{0.5});
}

// VREng's own eyes.fap numbers its frames 1..N under a header count of N: fapcast reads it as
// VREng plays it (in order), with a warning; one frame more is still past the count.
TEST(FapPlayers, OneBasedFramesAreReadAsVrengPlaysThem) {
  std::string mask68(2 * 68 - 1, ' ');
  for (int i = 0; i < 68; ++i) mask68[static_cast<std::size_t>(2 * i)] = i == 18 ? '1' : '0';
  std::string text = "2.1 eyes.fap 25 3\n";
  for (int k = 1; k <= 3; ++k) text += mask68 + "\n" + std::to_string(k) + " " + std::to_string(10 * k) + "\n";
  const FapTextRead r = read_fap_text(text, "eyes.fap");
  ASSERT_EQ(r.sequence.frames.size(), 3u);
  const PlayerRead vreng = test::vreng_read(text);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(double(r.sequence.frames[k].value(19)), vreng.frames[k].faps.at(19)[0]);
  EXPECT_TRUE(r.info.one_based);
  EXPECT_FALSE(r.info.skipped_frames);
  ASSERT_EQ(r.info.warnings.size(), 1u);
  EXPECT_EQ(r.info.warnings[0],
            "eyes.fap:7: one-based-frames: frames numbered from 1 up to the header's count of 3: read as 0..2 in order, as "
            "VREng plays them (Xface would index past its frames)");
  EXPECT_THROW(test::xface_read(text), test::PlayerCrash);  // as the real Xface
  try {
    read_fap_text(text + mask68 + "\n4 40\n", "eyes4.fap");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "eyes4.fap:9: frame-past-count: frame 4 is past the header's count of 3 frames");
  }
  // Numbered from 1 but not up to the count: as before, frame 0 neutral.
  const FapTextRead late = read_fap_text("2.1 late 25 3\n" + mask68 + "\n1 10\n", "late.fap");
  EXPECT_FALSE(late.info.one_based);
  EXPECT_TRUE(late.sequence.frames[0].mask.none());
}

}  // namespace
}  // namespace fapcast
