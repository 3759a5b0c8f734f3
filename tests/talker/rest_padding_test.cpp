// Rest before and after a take: the audio grows by silence, every position moves with it, and the
// edges become silences that reach the new ends, whether espeak-ng gave an edge pause or not.
#include "fapcast/talker/rest_padding.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace fapcast {
namespace {

// 100 samples at 1 kHz: "a" (AH 10-60) then T (60-100), as espeak-ng reports a word with no edge pauses.
Speech word_without_pauses() {
  Speech s;
  s.audio.sample_rate = SampleRate{1000};
  s.audio.samples.assign(100, 7);
  s.phones = {{Phone::AH, 10, 60}, {Phone::T, 60, 100}};
  s.events = {{10, 10, 0, "V"}, {60, 70, 0, "t"}};
  s.words = {{"ut", 0, 10, 100}};
  return s;
}

TEST(RestPadding, AddsSilenceAndShiftsEveryPosition) {
  const Speech s = with_rest(word_without_pauses(), {0.25, 0.35});
  ASSERT_EQ(s.audio.instants(), 250 + 100 + 350);
  EXPECT_TRUE(std::all_of(s.audio.samples.begin(), s.audio.samples.begin() + 250, [](auto v) { return v == 0; }));
  EXPECT_EQ(s.audio.samples[250], 7);
  EXPECT_EQ(s.audio.samples[349], 7);
  EXPECT_TRUE(std::all_of(s.audio.samples.begin() + 350, s.audio.samples.end(), [](auto v) { return v == 0; }));
  // The new silence covers what was added and the unlabelled start before the first phone.
  ASSERT_EQ(s.phones.size(), 4u);
  EXPECT_EQ(s.phones[0], (TimedPhone{Phone::SIL, 0, 260}));
  EXPECT_EQ(s.phones[1], (TimedPhone{Phone::AH, 260, 310}));
  EXPECT_EQ(s.phones[2], (TimedPhone{Phone::T, 310, 350}));
  EXPECT_EQ(s.phones[3], (TimedPhone{Phone::SIL, 350, 700}));
  ASSERT_EQ(s.events.size(), s.phones.size());  // still one per phone
  EXPECT_EQ(s.events[0].word, kNoWord);
  EXPECT_EQ(s.events[2].release_sample, 320);
  EXPECT_EQ(s.events[3].event_sample, 350);
  EXPECT_EQ(s.words[0].start_sample, 260);
  EXPECT_EQ(s.words[0].end_sample, 350);
}

TEST(RestPadding, EdgePausesAreExtendedNotDoubled) {
  Speech in = word_without_pauses();
  in.phones = {{Phone::SIL, 0, 10}, {Phone::AH, 10, 60}, {Phone::T, 60, 95}, {Phone::SIL, 95, 100}};
  in.events.insert(in.events.begin(), PhoneEvent{0, 0, kNoWord, "_"});
  in.events.push_back(PhoneEvent{95, 95, kNoWord, "_"});
  const Speech s = with_rest(in, {0.1, 0.2});
  ASSERT_EQ(s.phones.size(), 4u);
  EXPECT_EQ(s.phones.front(), (TimedPhone{Phone::SIL, 0, 110}));
  EXPECT_EQ(s.phones.back(), (TimedPhone{Phone::SIL, 195, 400}));
  EXPECT_EQ(s.events.size(), 4u);
}

TEST(RestPadding, NoPaddingChangesNothingAndNegativeIsRefused) {
  const Speech in = word_without_pauses();
  const Speech s = with_rest(in, {0, 0});
  EXPECT_EQ(s.audio.samples, in.audio.samples);
  EXPECT_EQ(s.phones, in.phones);
  EXPECT_THROW(with_rest(in, {-0.1, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
