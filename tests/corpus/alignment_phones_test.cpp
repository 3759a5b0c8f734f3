// Timed phones from alignment segments: ARPAbet and TIMIT labels, gaps, closure + release,
// EMU compounds and aspiration, bad labels; and fitting them to the audio.
#include "fapcast/corpus/alignment_phones.hpp"

#include "fapcast/core/input_error.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

LabelTier tier(std::vector<Interval> intervals, std::string name = "phones") {
  LabelTier t{std::move(name), TierKind::intervals, 0.0, intervals.empty() ? 0.0 : intervals.back().end_s, std::move(intervals), {}};
  return t;
}

TEST(AlignmentPhones, ReadsArpabetTimitAndGaps) {
  const LabelTier t = tier({{0.0, 0.1, ""}, {0.1, 0.2, "HH"}, {0.2, 0.35, "AH0"}, {0.35, 0.4, "pau"},
                            {0.4, 0.45, "dcl"}, {0.45, 0.5, "d"}, {0.5, 0.6, "ix"}, {0.6, 0.7, "sil"}});
  const auto segments = segments_of(t, LabelSet::timit, "a.TextGrid");
  const auto p = timed_phones(segments, SampleRate{16000}, "a.TextGrid");
  ASSERT_EQ(p.size(), 7u);
  EXPECT_EQ(p[0].phone, Phone::SIL);
  EXPECT_EQ(p[1].phone, Phone::HH);
  EXPECT_EQ(p[2].phone, Phone::AX) << "AH0 is CMUdict's schwa";
  EXPECT_EQ(p[3].phone, Phone::SIL);
  EXPECT_EQ(p[4].phone, Phone::D) << "closure + release merged";
  EXPECT_EQ(p[4].start_sample, 6400);
  EXPECT_EQ(p[4].end_sample, 8000);
  EXPECT_DOUBLE_EQ(segments[4].start_s, 0.4);
  EXPECT_DOUBLE_EQ(segments[4].release_s, 0.45) << "the joined segment keeps where its release starts";
  EXPECT_EQ(p[5].phone, Phone::IH);
  EXPECT_EQ(p[6].end_sample, 11200);
}

// MOCHA's breath: a pause where alignments are compared; where the animation asks for it, an
// inhalation with the mouth open (AX) that runs on over the pause after it to the next phone.
TEST(AlignmentPhones, ABreathIsAPauseOrAnInhalation) {
  const LabelTier t = tier({{0.0, 0.25, "sil"}, {0.25, 0.28, "breath"}, {0.28, 0.35, "sil"}, {0.35, 0.42, "dh"}});
  const auto segments = segments_of(t, LabelSet::mocha, "m.lab");
  ASSERT_EQ(segments.size(), 4u);
  EXPECT_EQ(segments[1].kind, LabelKind::breath);
  EXPECT_EQ(segments[1].phone, Phone::SIL);
  const auto compared = timed_phones(segments, SampleRate{16000}, "m.lab");
  ASSERT_EQ(compared.size(), 4u);
  EXPECT_EQ(compared[1].phone, Phone::SIL);
  EXPECT_EQ(compared[1].end_sample, 4480) << "compared as a pause, the breath keeps its own span";
  const auto animated = timed_phones(segments, SampleRate{16000}, "m.lab", kInhalation);
  ASSERT_EQ(animated.size(), 3u) << "the 70 ms pause after the breath is the inhalation's";
  EXPECT_EQ(animated[0].phone, Phone::SIL);
  EXPECT_EQ(animated[0].end_sample, 4000);
  EXPECT_EQ(animated[1].phone, Phone::AX);
  EXPECT_EQ(animated[1].start_sample, 4000);
  EXPECT_EQ(animated[1].end_sample, 5600) << "the mouth stays open until the first phone";
  EXPECT_EQ(animated[2].phone, Phone::DH);
  EXPECT_EQ(animated[2].start_sample, 5600);
}

// The run-on is bounded: a long pause after a breath is the inhalation's for 0.3 s, then rest; a
// breath right before a phone keeps its span; silences in a row are taken in turn.
TEST(AlignmentPhones, ABreathRunsOnAtMostItsLimit) {
  const LabelTier t = tier({{0.0, 0.2, "breath"}, {0.2, 1.2, "sil"}, {1.2, 1.3, "breath"}, {1.3, 1.4, "dh"},
                            {1.4, 1.5, "breath"}, {1.5, 1.6, "sil"}, {1.6, 1.65, "sil"}, {1.65, 2.5, "sil"}, {2.5, 2.6, "s"}});
  const auto animated = timed_phones(segments_of(t, LabelSet::mocha, "m.lab"), SampleRate{10000}, "m.lab", kInhalation);
  ASSERT_EQ(animated.size(), 7u);
  EXPECT_EQ(animated[0].phone, Phone::AX);
  EXPECT_EQ(animated[0].end_sample, 5000) << "0.2 s + 0.3 s";
  EXPECT_EQ(animated[1].phone, Phone::SIL);
  EXPECT_EQ(animated[1].start_sample, 5000);
  EXPECT_EQ(animated[1].end_sample, 12000);
  EXPECT_EQ(animated[2].phone, Phone::AX);
  EXPECT_EQ(animated[2].end_sample, 13000) << "no pause after it: its own span";
  EXPECT_EQ(animated[3].phone, Phone::DH);
  EXPECT_EQ(animated[4].phone, Phone::AX);
  EXPECT_EQ(animated[4].end_sample, 18000) << "two silences taken whole and 0.15 s of the third";
  EXPECT_EQ(animated[5].phone, Phone::SIL);
  EXPECT_EQ(animated[5].start_sample, 18000);
  EXPECT_EQ(animated[5].end_sample, 25000);
  EXPECT_EQ(animated[6].phone, Phone::S);
  // Every sample keeps exactly one phone.
  for (std::size_t i = 1; i < animated.size(); ++i) EXPECT_EQ(animated[i].start_sample, animated[i - 1].end_sample) << i;
}

TEST(AlignmentPhones, CompoundsSplitAndAspirationJoins) {
  // EMU ae: "k H" is one K with its aspiration; "db" is D then B in halves of its interval.
  const LabelTier t = tier({{0.0, 0.1, "k"}, {0.1, 0.14, "H"}, {0.14, 0.24, "db"}});
  const auto p = timed_phones(segments_of(t, LabelSet::emu_ae, "e.lab"), SampleRate{10000}, "e.lab");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].phone, Phone::K);
  EXPECT_EQ(p[0].end_sample, 1400);
  EXPECT_EQ(p[1].phone, Phone::D);
  EXPECT_EQ(p[1].end_sample, 1900);
  EXPECT_EQ(p[2].phone, Phone::B);
  EXPECT_EQ(p[2].start_sample, 1900);
}

TEST(AlignmentPhones, BadLabelNamesFileIntervalAndLabel) {
  try {
    (void)segments_of(tier({{0.0, 0.1, "sil"}, {0.1, 0.2, "xyz"}}), LabelSet::arpabet, "b.lab");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "alignment-unknown-label");
    EXPECT_STREQ(e.what(), "b.lab: alignment-unknown-label: interval 2 (0.1 to 0.2 s) of tier \"phones\": \"xyz\" is "
                           "not an ARPAbet label (--phone-set names another set)");
  }
}

TEST(AlignmentPhones, ALabFileReadsTheSameWay) {
  const std::string lab = "0 1000000 sil\n1000000 2500000 m\n2500000 4000000 aa\n";
  const AlignmentFile f = read_alignment_file(lab, "c.lab", {});
  const auto p = timed_phones(f.segments, SampleRate{22050}, "c.lab");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1].phone, Phone::M);
  EXPECT_EQ(p[2].end_sample, to_sample(0.4, SampleRate{22050}));
}

TEST(AlignmentPhones, ATimeOffTheSampleGridIsTheFilesFault) {
  std::vector<AlignedSegment> segments(1);
  segments[0].end_s = 1e300;
  segments[0].phone = Phone::AA;
  segments[0].label = "aa";
  try {
    (void)timed_phones(segments, SampleRate{16000}, "huge.lab");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "time-off-sample-grid");
    EXPECT_STREQ(e.what(), "huge.lab: time-off-sample-grid: segment 1 'aa': time 1e+300 s is off the sample grid of 16000 Hz");
  }
}

TEST(FitPhonesToAudio, CutsWithinToleranceRefusesBeyond) {
  std::vector<TimedPhone> p{{Phone::SIL, 0, 100}, {Phone::AA, 100, 200},
                            {Phone::SIL, 200, 230}};
  auto fitted = fit_phones_to_audio(p, 195, 50, "x.lab");
  ASSERT_EQ(fitted.size(), 2u) << "the phone starting after the audio's end is dropped";
  EXPECT_EQ(fitted.back().end_sample, 195);
  EXPECT_EQ(fit_phones_to_audio(p, 1000, 0, "x.lab").back().end_sample, 230) << "shorter: unchanged";
  try {
    fit_phones_to_audio(p, 150, 50, "x.lab");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "alignment-longer-than-audio");
    EXPECT_NE(std::string(e.what()).find("x.lab"), std::string::npos);
  }
  EXPECT_TRUE(fit_phones_to_audio({}, 100, 0, "x").empty());
}

}  // namespace
}  // namespace fapcast
