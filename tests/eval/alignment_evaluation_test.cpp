// viseme_frame_agreement: 10 ms frames of a reference phone sequence against a hypothesis, in
// the search viseme classes (spec/recognise.md, "Recognition"); and the reference list.
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "fapcast/eval/alignment_evaluation.hpp"
#include "fapcast/phonetics/viseme.hpp"

namespace fapcast {
namespace {

constexpr SampleRate kRate{16000};

TEST(AlignmentEvaluation, FramesCountedOverTheReferenceAndComparedByClass) {
  // 0.1 s: SIL 0-30 ms, P 30-60 ms, AA 60-100 ms
  const std::vector<TimedPhone> reference{{Phone::SIL, 0, 480}, {Phone::P, 480, 960}, {Phone::AA, 960, 1600}};
  const FrameAgreement same = viseme_frame_agreement(reference, reference, kRate);
  EXPECT_EQ(same.frames, 10u);
  EXPECT_EQ(same.in_class, 10u);
  EXPECT_DOUBLE_EQ(same.share(), 1.0);
  // B and M share P's class (lips closed): a different phone, the same class
  const std::vector<TimedPhone> bilabial{{Phone::SIL, 0, 480}, {Phone::M, 480, 960}, {Phone::AA, 960, 1600}};
  EXPECT_EQ(search_viseme(Phone::M), search_viseme(Phone::P));
  EXPECT_EQ(viseme_frame_agreement(reference, bilabial, kRate).in_class, 10u);
  // the hypothesis starts the vowel 20 ms late: frames at 65 and 75 ms are in P's class, wrong
  const std::vector<TimedPhone> late{{Phone::SIL, 0, 480}, {Phone::P, 480, 1280}, {Phone::AA, 1280, 1600}};
  EXPECT_EQ(viseme_frame_agreement(reference, late, kRate).in_class, 8u);
  // with 5 ms frames: 20 frames, 4 of them wrong
  const FrameAgreement fine = viseme_frame_agreement(reference, late, kRate, 0.005);
  EXPECT_EQ(fine.frames, 20u);
  EXPECT_EQ(fine.in_class, 16u);
  // a hypothesis shorter than the reference: its last phone stands for the rest
  const std::vector<TimedPhone> short_hyp{{Phone::SIL, 0, 480}, {Phone::P, 480, 960}, {Phone::AA, 960, 1200}};
  EXPECT_EQ(viseme_frame_agreement(reference, short_hyp, kRate).in_class, 10u);
  EXPECT_EQ(viseme_frame_agreement({}, reference, kRate).frames, 0u);
  EXPECT_DOUBLE_EQ(FrameAgreement{}.share(), 0.0);
}

TEST(AlignmentEvaluation, EveryReferenceRecordingIsVendored) {
  const auto all = reference_recordings(FAPCAST_TEST_DATA);
  ASSERT_GE(all.size(), 10u);
  for (const ReferenceRecording& r : all) {
    EXPECT_TRUE(std::filesystem::exists(r.wav)) << r.wav;
    EXPECT_TRUE(std::filesystem::exists(r.labels)) << r.labels;
    EXPECT_TRUE(std::filesystem::exists(r.transcript)) << r.transcript;
  }
}

}  // namespace
}  // namespace fapcast
