// Phones from alignments: ARPAbet and TIMIT labels, gaps, closure + release, bad labels.
#include "fapcast/corpus/alignment_phones.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/lab_file.hpp"
#include "fapcast/corpus/textgrid.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

LabelTier tier(std::vector<Interval> intervals, std::string name = "phones") {
  LabelTier t{std::move(name), TierKind::intervals, 0.0, intervals.empty() ? 0.0 : intervals.back().end_s, std::move(intervals), {}};
  return t;
}

TEST(AlignmentPhones, ReadsArpabetTimitAndGaps) {
  const auto p = phones_from_tier(tier({{0.0, 0.1, ""}, {0.1, 0.2, "HH"}, {0.2, 0.35, "AH0"}, {0.35, 0.4, "pau"},
                                        {0.4, 0.45, "dcl"}, {0.45, 0.5, "d"}, {0.5, 0.6, "ix"}, {0.6, 0.7, "sil"}}),
                                   SampleRate{16000}, "a.TextGrid");
  ASSERT_EQ(p.size(), 7u);
  EXPECT_EQ(p[0].phone, Phone::SIL);
  EXPECT_EQ(p[1].phone, Phone::HH);
  EXPECT_EQ(p[2].phone, Phone::AH);
  EXPECT_EQ(p[3].phone, Phone::SIL);
  EXPECT_EQ(p[4].phone, Phone::D) << "closure + release merged";
  EXPECT_EQ(p[4].start_sample, 6400);
  EXPECT_EQ(p[4].end_sample, 8000);
  EXPECT_EQ(p[5].phone, Phone::IH);
  EXPECT_EQ(p[6].end_sample, 11200);
}

TEST(AlignmentPhones, BadLabelNamesFileIntervalAndLabel) {
  try {
    phones_from_tier(tier({{0.0, 0.1, "sil"}, {0.1, 0.2, "xyz"}}), SampleRate{16000}, "b.lab");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "phone-label");
    const std::string what = e.what();
    EXPECT_NE(what.find("b.lab"), std::string::npos) << what;
    EXPECT_NE(what.find("interval 2"), std::string::npos) << what;
    EXPECT_NE(what.find("'xyz'"), std::string::npos) << what;
  }
}

TEST(AlignmentPhones, FindsThePhoneTier) {
  Alignment a;
  a.tiers.push_back(tier({{0, 1, "hello"}}, "words"));
  EXPECT_EQ(phone_tier(a), &a.tiers[0]) << "no phone tier: the first interval tier";
  a.tiers.push_back(tier({{0, 1, "sil"}}, "Phones"));
  EXPECT_EQ(phone_tier(a), &a.tiers[1]);
  EXPECT_EQ(phone_tier(Alignment{}), nullptr);
  // A .lab file's tier works the same.
  const LabFile lab = read_lab("0 1000000 sil\n1000000 2500000 m\n2500000 4000000 aa\n", "c.lab");
  const auto p = phones_from_tier(to_tier(lab, "phones"), SampleRate{22050}, "c.lab");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1].phone, Phone::M);
  EXPECT_EQ(p[2].end_sample, to_sample(0.4, SampleRate{22050}));
}

}  // namespace
}  // namespace fapcast

namespace fapcast {
namespace {

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
