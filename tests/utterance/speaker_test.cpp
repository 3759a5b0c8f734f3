// A voice speaking sentence by sentence: the FAP frames and the morph weights of one sentence
// cover its audio at the output rate, frame for frame; the weights are the PCA frames the
// synthesiser made (resampled exactly); resample_rows interpolates at exact rational positions.
#include "fapcast/utterance/speaker.hpp"

#include "fapcast/core/frame_rate.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/utterance/fap_track.hpp"
#include "support/spoken_voice.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

TEST(ResampleRows, InterpolatesAtExactPositionsAndHoldsTheEnd) {
  Eigen::MatrixXf rows(4, 2);
  rows << 0, 10, 6, 16, 12, 22, 18, 28;  // 60 fps
  const Eigen::MatrixXf at25 = resample_rows(rows, {60, 1}, {25, 1}, 3);
  // Row j at j * 60 / 25 = 2.4 j input rows.
  EXPECT_FLOAT_EQ(at25(0, 0), 0.f);
  EXPECT_FLOAT_EQ(at25(1, 0), 12.f + 0.4f * 6.f);
  EXPECT_FLOAT_EQ(at25(1, 1), 22.f + 0.4f * 6.f);
  EXPECT_FLOAT_EQ(at25(2, 0), 18.f);  // 4.8: past the last row, held
  const Eigen::MatrixXf same = resample_rows(rows, {60, 1}, {60, 1}, 4);
  EXPECT_EQ(same, rows);
  const Eigen::MatrixXf ntsc = resample_rows(rows, {60, 1}, {30000, 1001}, 2);
  EXPECT_FLOAT_EQ(ntsc(1, 0), 6.f * (2.0f * 1001.f / 1000.f));  // 2.002 rows
}

TEST(Speaker, OneSentenceIsItsAudioWithFramesAndWeightsAtTheOutputRate) {
  const Voice voice = Voice::open(test::spoken_voice_file());
  SpeakerSettings settings;
  settings.rate = {25, 1};
  const Speaker speaker(voice, settings, "test voice");
  const SpokenSentence s = speaker.speak("Bob bought a big blue boat.");
  ASSERT_GT(s.audio.samples.size(), 0u);
  ASSERT_FALSE(s.phones.empty());
  const auto samples = static_cast<std::int64_t>(s.audio.samples.size());
  EXPECT_EQ(static_cast<std::int64_t>(s.faps.frames.size()), frames_shown(samples, {25, 1}, s.audio.sample_rate));
  EXPECT_EQ(s.weights.rows(), static_cast<Eigen::Index>(s.faps.frames.size()));
  EXPECT_EQ(s.weights.cols(), speaker.components());
  EXPECT_GT(s.speech_time.count(), 0);
  // The lips move: some frame's FAP 5 (raise_b_midlip) differs from the first frame's.
  bool moved = false;
  for (const FapFrame& f : s.faps.frames) moved |= f.value(5) != s.faps.frames.front().value(5);
  EXPECT_TRUE(moved);
  // The weights are the synthesiser's: frame 0 is the track's first 60 fps frame.
  const SynthesizedTrack track = synthesize(voice, s.phones, s.audio.sample_rate, samples, settings.synthesis, "t");
  EXPECT_TRUE(s.weights.row(0).isApprox(track.pca_frames.row(0)));
  EXPECT_TRUE(s.weights.row(5).isApprox(track.pca_frames.row(12)));  // 5 * 60 / 25 = 12 exactly
}

TEST(Speaker, EmptyTextIsAnEmptySentenceAndBadTextAnInputError) {
  const Voice voice = Voice::open(test::spoken_voice_file());
  const Speaker speaker(voice, {}, "test voice");
  const SpokenSentence empty = speaker.speak("   ");
  EXPECT_TRUE(empty.audio.samples.empty());
  EXPECT_TRUE(empty.faps.frames.empty());
  EXPECT_THROW((void)speaker.speak(std::string("bad \x01 text")), InputError);
}

TEST(Speaker, AnExpressionPutsFap2InEveryFrame) {
  const Voice voice = Voice::open(test::spoken_voice_file());
  SpeakerSettings settings;
  settings.expression = parse_expression_blend("joy:40");
  const Speaker speaker(voice, settings, "test voice");
  const SpokenSentence s = speaker.speak("Hello.");
  ASSERT_FALSE(s.faps.frames.empty());
  for (const FapFrame& f : s.faps.frames) {
    ASSERT_TRUE(f.mask.test(kExpressionFap));
    EXPECT_EQ(f.expression.intensity1, 40);
  }
  EXPECT_EQ(s.weights.cols(), speaker.components()) << "the weights are the PCA ones; the expression is the session's";
}

// The front-end's options reach espeak-ng: SSML markup is parsed, not spoken.
TEST(Speaker, SpeaksSsmlWhenTheSettingsSaySo) {
  const Voice voice = Voice::open(test::spoken_voice_file());
  SpeakerSettings ssml;
  ssml.speech.ssml = true;
  const SpokenSentence marked = Speaker(voice, ssml, "test voice").speak("<speak>Bob bought a boat.</speak>");
  const SpokenSentence plain = Speaker(voice, {}, "test voice").speak("Bob bought a boat.");
  const auto spoken = [](const SpokenSentence& s) {  // the phones, silences left out
    std::vector<Phone> phones;
    for (const TimedPhone& p : s.phones)
      if (p.phone != Phone::SIL) phones.push_back(p.phone);
    return phones;
  };
  ASSERT_FALSE(spoken(plain).empty());
  EXPECT_EQ(spoken(marked), spoken(plain));
  EXPECT_FALSE(marked.faps.frames.empty());
}

}  // namespace
}  // namespace fapcast
