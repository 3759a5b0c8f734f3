// The mouth-cue rules of spec/mouth-cues.md on hand-made phone tracks: each phone's shapes,
// vowel anticipation, the closure before a plosive, pauses by length, the in-betweens and the
// shapes a character lacks; and the invariants every cue track keeps.
#include "fapcast/cues/mouth_cues.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace fapcast {
namespace {

// At 100 Hz a sample is a centisecond: the tracks below read in cs.
constexpr SampleRate kCs{100};

// "P:10 AA:30" -> contiguous phones from 0.
std::vector<TimedPhone> track(std::initializer_list<std::pair<Phone, std::int64_t>> phones) {
  std::vector<TimedPhone> out;
  std::int64_t t = 0;
  for (const auto& [p, length] : phones) {
    out.push_back({p, t, t + length});
    t += length;
  }
  return out;
}

std::int64_t end_of(const std::vector<TimedPhone>& phones) { return phones.back().end_sample; }

// The cues as "X0-5 D5-37 ..." for readable failures.
std::string text(const std::vector<MouthCue>& cues) {
  std::string out;
  for (const MouthCue& c : cues)
    out += (out.empty() ? "" : " ") + std::string(1, letter(c.shape)) + std::to_string(c.start.count()) + "-" +
           std::to_string(c.end.count());
  return out;
}

// The shape shown at centisecond `t`.
MouthShape at(const std::vector<MouthCue>& cues, std::int64_t t) {
  for (const MouthCue& c : cues)
    if (c.start.count() <= t && t < c.end.count()) return c.shape;
  ADD_FAILURE() << "no cue at " << t << " in " << text(cues);
  return MouthShape::X;
}

void expect_well_formed(const std::vector<MouthCue>& cues, Centiseconds duration, MouthShapeSet drawn) {
  ASSERT_FALSE(cues.empty());
  EXPECT_EQ(cues.front().start, Centiseconds{0});
  EXPECT_EQ(cues.back().end, duration);
  for (std::size_t i = 0; i < cues.size(); ++i) {
    EXPECT_LT(cues[i].start, cues[i].end) << text(cues);
    EXPECT_TRUE(drawn.contains(cues[i].shape)) << letter(cues[i].shape) << " in " << text(cues);
    if (i > 0) {
      EXPECT_EQ(cues[i].start, cues[i - 1].end) << text(cues);
      EXPECT_NE(cues[i].shape, cues[i - 1].shape) << text(cues);
    }
  }
}

TEST(MouthShape, TableIsInEnumOrderWithRhubarbsBasicShapes) {
  for (std::size_t i = 0; i < kMouthShapeCount; ++i) EXPECT_EQ(static_cast<std::size_t>(kMouthShapeTable[i].shape), i);
  EXPECT_EQ(std::string("ABCDEFGHX"), [] {
    std::string s;
    for (const auto& row : kMouthShapeTable) s += row.letter;
    return s;
  }());
  EXPECT_EQ(mouth_shape_info(MouthShape::G).basic, MouthShape::A);
  EXPECT_EQ(mouth_shape_info(MouthShape::H).basic, MouthShape::C);
  EXPECT_EQ(mouth_shape_info(MouthShape::X).basic, MouthShape::A);
  EXPECT_EQ(mouth_shape_from_letter('H'), MouthShape::H);
  EXPECT_EQ(mouth_shape_from_letter('h'), std::nullopt);
  EXPECT_EQ(mouth_shape_from_letter('I'), std::nullopt);
}

TEST(MouthShape, ExtendedShapesReadAsRhubarbsOption) {
  EXPECT_EQ(drawn_shapes("GHX"), MouthShapeSet::all());
  EXPECT_EQ(extended_letters(*drawn_shapes("XG")), "GX");
  EXPECT_EQ(extended_letters(*drawn_shapes("")), "");
  EXPECT_EQ(drawn_shapes("")->size(), 6u);
  EXPECT_EQ(drawn_shapes("GG"), std::nullopt);  // twice
  EXPECT_EQ(drawn_shapes("A"), std::nullopt);   // a basic shape is always drawn
  EXPECT_EQ(drawn_shapes("gx"), std::nullopt);
}

// Rhubarb README's 'Hi': the mouth opens wide already for HH (anticipating AY), AY's second half
// clenches the teeth (B) with C in between, and the mouth rests (X) before and after.
TEST(MouthCues, HiAnticipatesTheVowelAndTweensDownToB) {
  const auto phones = track({{Phone::SIL, 5}, {Phone::HH, 10}, {Phone::AY, 40}, {Phone::SIL, 20}});
  const auto cues = mouth_cues(phones, kCs, end_of(phones));
  // AY 15-55: D over 60 % (15-39), B after; the centred C is min(24/4, 16/4, 8) = 4 cs around 39.
  EXPECT_EQ(text(cues), "X0-5 D5-37 C37-41 B41-55 X55-75");
}

TEST(MouthCues, LipsCloseBeforeABilabialPlosive) {
  const auto phones = track({{Phone::SIL, 10}, {Phone::AA, 30}, {Phone::P, 10}, {Phone::AA, 30}, {Phone::SIL, 20}});
  const auto cues = mouth_cues(phones, kCs, end_of(phones));
  // The closure: half the AA before (15 cs) capped at 12 cs, ending where P starts (40).
  EXPECT_EQ(at(cues, 28), MouthShape::A);
  EXPECT_EQ(at(cues, 39), MouthShape::A);
  EXPECT_NE(at(cues, 27), MouthShape::A);
  EXPECT_EQ(at(cues, 40), MouthShape::D);  // the release anticipates the next AA
  // D -> A tweens early through C: a third of D's 18 cs, at most 8 cs. D -> X late, into the pause.
  EXPECT_EQ(text(cues), "X0-10 D10-22 C22-28 A28-40 D40-80 C80-86 X86-100");
}

TEST(MouthCues, EachPhoneShowsItsShape) {
  const auto shape_of = [](Phone p, std::int64_t length, MouthShapeSet drawn = MouthShapeSet::all()) {
    const auto phones = track({{Phone::SIL, 50}, {p, length}, {Phone::SIL, 50}});
    MouthCueOptions options;
    options.drawn = drawn;
    const auto cues = mouth_cues(phones, kCs, end_of(phones), options);
    return at(cues, 50 + length / 2);
  };
  EXPECT_EQ(shape_of(Phone::AA, 20), MouthShape::D);
  EXPECT_EQ(shape_of(Phone::AE, 20), MouthShape::C);
  EXPECT_EQ(shape_of(Phone::AH, 10), MouthShape::C);  // short AH opens less
  EXPECT_EQ(shape_of(Phone::AH, 30), MouthShape::D);
  EXPECT_EQ(shape_of(Phone::IY, 20), MouthShape::B);
  EXPECT_EQ(shape_of(Phone::UW, 20), MouthShape::F);
  EXPECT_EQ(shape_of(Phone::AO, 20), MouthShape::E);
  EXPECT_EQ(shape_of(Phone::ER, 20), MouthShape::E);
  EXPECT_EQ(shape_of(Phone::W, 20), MouthShape::F);
  EXPECT_EQ(shape_of(Phone::M, 20), MouthShape::A);
  EXPECT_EQ(shape_of(Phone::F, 20), MouthShape::G);
  EXPECT_EQ(shape_of(Phone::V, 20), MouthShape::G);
  EXPECT_EQ(shape_of(Phone::L, 30), MouthShape::H);  // a long L shows the tongue
  // Without the extended drawings, their basic shapes: G -> A, H -> C.
  EXPECT_EQ(shape_of(Phone::F, 20, *drawn_shapes("")), MouthShape::A);
  EXPECT_EQ(shape_of(Phone::L, 30, *drawn_shapes("GX")), MouthShape::C);
}

TEST(MouthCues, DiphthongsChangeShapeAtSixtyPercent) {
  const auto phones = track({{Phone::SIL, 50}, {Phone::OW, 50}, {Phone::SIL, 50}});
  const auto cues = mouth_cues(phones, kCs, end_of(phones));
  EXPECT_EQ(at(cues, 60), MouthShape::E);
  EXPECT_EQ(at(cues, 85), MouthShape::F);
}

TEST(MouthCues, PausesHoldRelaxOrRestByLength) {
  // AA, a pause of `gap` cs, AA again.
  const auto middle = [](std::int64_t gap, MouthShapeSet drawn) {
    const auto phones = track({{Phone::SIL, 20}, {Phone::AA, 40}, {Phone::SIL, gap}, {Phone::AA, 40}, {Phone::SIL, 20}});
    MouthCueOptions options;
    options.drawn = drawn;
    const auto cues = mouth_cues(phones, kCs, end_of(phones), options);
    expect_well_formed(cues, Centiseconds{end_of(phones)}, drawn);
    return at(cues, 60 + gap / 2);
  };
  EXPECT_EQ(middle(8, MouthShapeSet::all()), MouthShape::D);   // < 12 cs: the mouth holds its shape
  EXPECT_EQ(middle(25, MouthShapeSet::all()), MouthShape::C);  // 12-35 cs: it relaxes a step (D -> C)
  EXPECT_EQ(middle(60, MouthShapeSet::all()), MouthShape::X);  // longer: it rests
  // The same rules when the drawings have no X: a short pause still holds D (it does not snap
  // shut to A), and only the rest is shown as A.
  EXPECT_EQ(middle(5, *drawn_shapes("")), MouthShape::D);
  EXPECT_EQ(middle(25, *drawn_shapes("")), MouthShape::C);
  EXPECT_EQ(middle(60, *drawn_shapes("")), MouthShape::A);
}

TEST(MouthCues, SilenceAndUncoveredTimeRest) {
  // Phones from 30 to 60 cs of a 100 cs recording: before and after, the mouth rests.
  const std::vector<TimedPhone> phones{{Phone::M, 30, 40}, {Phone::IY, 40, 60}};
  const auto cues = mouth_cues(phones, kCs, 100);
  expect_well_formed(cues, Centiseconds{100}, MouthShapeSet::all());
  EXPECT_EQ(cues.front().shape, MouthShape::X);
  EXPECT_EQ(cues.back().shape, MouthShape::X);
  EXPECT_EQ(at(cues, 35), MouthShape::A);
  EXPECT_EQ(at(cues, 50), MouthShape::B);
  // Without X, rest is the closed mouth A.
  MouthCueOptions options;
  options.drawn = *drawn_shapes("GH");
  const auto closed = mouth_cues(phones, kCs, 100, options);
  EXPECT_EQ(closed.front().shape, MouthShape::A);
  EXPECT_EQ(closed.back().shape, MouthShape::A);
}

TEST(MouthCues, TimesTruncateToCentiseconds) {
  const SampleRate rate{22050};
  // 0.1049 s of silence, then AA to 0.5 s, in a recording of 0.6199 s.
  const std::vector<TimedPhone> phones{{Phone::SIL, 0, 2313}, {Phone::AA, 2313, 11025}};
  const auto cues = mouth_cues(phones, rate, 13669);
  expect_well_formed(cues, Centiseconds{61}, MouthShapeSet::all());
  EXPECT_EQ(truncated_centiseconds(2313, rate), Centiseconds{10});
  EXPECT_EQ(at(cues, 9), MouthShape::X);
  EXPECT_EQ(at(cues, 10), MouthShape::D);
}

TEST(MouthCues, EveryTrackKeepsTheInvariants) {
  std::mt19937 random(18);
  std::uniform_int_distribution<int> phone(0, static_cast<int>(kPhoneCount) - 1);
  std::uniform_int_distribution<std::int64_t> length(1, 400);  // samples at 1 kHz: 1 ms to 0.4 s
  const SampleRate rate{1000};
  for (const char* extended : {"GHX", "", "X", "GH"}) {
    const MouthShapeSet drawn = *drawn_shapes(extended);
    for (int round = 0; round < 50; ++round) {
      std::vector<TimedPhone> phones;
      std::int64_t t = length(random) / 4;
      for (int i = 0; i < 60; ++i) {
        const std::int64_t l = length(random);
        phones.push_back({static_cast<Phone>(phone(random)), t, t + l});
        t += l + (random() % 5 == 0 ? length(random) : 0);  // now and then a gap
      }
      MouthCueOptions options;
      options.drawn = drawn;
      const std::int64_t samples = t + 123;
      const auto cues = mouth_cues(phones, rate, samples, options);
      expect_well_formed(cues, truncated_centiseconds(samples, rate), drawn);
      if (HasFailure()) return;
    }
  }
}

TEST(MouthCues, EmptyRecordingHasNoCues) {
  EXPECT_TRUE(mouth_cues({}, kCs, 0).empty());
  const auto cues = mouth_cues({}, kCs, 50);
  ASSERT_EQ(cues.size(), 1u);
  EXPECT_EQ(cues[0], (MouthCue{MouthShape::X, Centiseconds{0}, Centiseconds{50}}));
}

TEST(MouthCues, OverlappingPhonesAreACallersBug) {
  const std::vector<TimedPhone> phones{{Phone::AA, 0, 50}, {Phone::B, 40, 60}};
  EXPECT_THROW(mouth_cues(phones, kCs, 60), std::invalid_argument);
  EXPECT_THROW(mouth_cues(phones, SampleRate{0}, 60), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
