// The jaw guide of the search's jaw term (synthesis/jaw_guide.hpp): each state's recorded chin
// opening and each phone's mean in units of the speech states' spread, and the wanted opening
// of a target timeline.
#include "fapcast/synthesis/jaw_guide.hpp"
#include "fapcast/synthesis/synthesis.hpp"

#include "support/target_timeline.hpp"
#include "support/tiny_voice.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

using V = VisemeClass;

// A tiny voice whose chin (FP 2.1) is vertex 0: component 0 moves its y, so a frame's chin opening
// is minus its coefficient. One take: rest (opening 0), M (-1 mm) over two frames, AA (+3 mm) over
// two: the speech states' mean is 1 mm and their spread 2 mm.
test::TinyVoice chin_voice(const std::string& chin_label = "2.1") {
  test::TinyVoice tiny;
  tiny.coefficients = RowMajorMatrixXf{{0.f}, {0.001f}, {0.001f}, {-0.003f}, {-0.003f}};
  tiny.graph.utterances = {{0, 5}};
  tiny.graph.frame_count = 5;
  tiny.graph.states = {{0, V::kSilence, {0, 1}}, {0, V::kBilabial, {1, 2}}, {0, V::kOpenUnrounded, {3, 2}}};
  tiny.graph.phones = {Phone::SIL, Phone::M, Phone::AA};
  const std::vector<VoiceFeaturePoint> points = {{chin_label, 0, {0.0, -0.06, 0.08}}};
  const std::vector<VoiceRigidMarker> rigid = {{"H.temple_l", 0, {0.07, 0.03, 0.0}, {0.07, 0.03, 0.01}},
                                               {"H.temple_r", 1, {-0.07, 0.03, 0.0}, {-0.07, 0.03, 0.01}},
                                               {"H.nose_bridge", 2, {0.0, 0.04, 0.09}, {0.0, 0.04, 0.1}}};
  tiny.feature_points = voice_feature_points_json(points, rigid);
  return tiny;
}

TEST(JawGuide, MeasuresTheChinInUnitsOfTheSpeechStatesSpread) {
  const Voice voice = chin_voice().open("fapcast_jaw_guide.fapv");
  const JawGuide guide = make_jaw_guide(voice);
  EXPECT_NEAR(guide.spread_mm, 2.0, 1e-4);
  ASSERT_EQ(guide.state_opening.size(), 3u);
  EXPECT_NEAR(guide.state_opening[0], -0.5f, 1e-4f);  // the rest: 0 mm, half a spread below the mean
  EXPECT_NEAR(guide.state_opening[1], -1.0f, 1e-4f);
  EXPECT_NEAR(guide.state_opening[2], 1.0f, 1e-4f);
  EXPECT_NEAR(guide.phone_opening[static_cast<std::size_t>(Phone::M)], -1.0f, 1e-4f);
  EXPECT_NEAR(guide.phone_opening[static_cast<std::size_t>(Phone::AA)], 1.0f, 1e-4f);
  EXPECT_EQ(guide.phone_opening[static_cast<std::size_t>(Phone::IY)], 0.0f) << "a phone never recorded wants the mean";
}

TEST(JawGuide, RefusesAVoiceWithoutAChinOrWithAStillOne) {
  const Voice no_chin = chin_voice("2.2").open("fapcast_jaw_guide_no_chin.fapv");
  try {
    (void)make_jaw_guide(no_chin);
    FAIL() << "a voice without FP 2.1 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "jaw-guide");
    EXPECT_NE(std::string(e.what()).find("2.1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("fapcast_jaw_guide_no_chin.fapv"), std::string::npos) << "names the voice: " << e.what();
  }
  test::TinyVoice still = chin_voice();
  still.coefficients = RowMajorMatrixXf{{0.f}, {0.001f}, {0.001f}, {0.001f}, {0.001f}};
  const Voice still_voice = still.open("fapcast_jaw_guide_still.fapv");
  try {
    (void)make_jaw_guide(still_voice);
    FAIL() << "a voice whose chin does not move was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "jaw-guide") << e.what();
  }
}

TEST(JawGuide, WantsEachPhonesOpeningSmoothedAcrossItsNeighbours) {
  const Voice voice = chin_voice().open("fapcast_jaw_guide_wanted.fapv");
  const JawGuide guide = make_jaw_guide(voice);
  // Held long, a phone reaches its own opening.
  const auto held = wanted_jaw(guide, test::target_timeline({{Phone::AA, 120}}), 4.0);
  ASSERT_EQ(held.size(), 1u);
  EXPECT_NEAR(held[0], 1.0f, 1e-4f);
  // Two long phones: each near its own, pulled towards the other near the boundary, symmetric.
  const auto pair = wanted_jaw(guide, test::target_timeline({{Phone::M, 60}, {Phone::AA, 60}}), 4.0);
  ASSERT_EQ(pair.size(), 2u);
  EXPECT_LT(pair[0], -0.8f);
  EXPECT_GT(pair[0], -1.0f);
  EXPECT_NEAR(pair[0], -pair[1], 0.02f);
  // A short M between open vowels does not close the jaw: the smoothing shares the vowels' opening.
  const auto brief = wanted_jaw(guide, test::target_timeline({{Phone::AA, 30}, {Phone::M, 3}, {Phone::AA, 30}}), 4.0);
  EXPECT_GT(brief[1], 0.0f);
  const auto slower = wanted_jaw(guide, test::target_timeline({{Phone::AA, 30}, {Phone::M, 3}, {Phone::AA, 30}}), 20.0);
  EXPECT_LT(slower[1], brief[1]) << "a higher cut-off lets the jaw follow a brief phone further";
  // A timeline that starts later gives the same (pieces of a long text).
  TargetTimeline later = test::target_timeline({{Phone::M, 60}, {Phone::AA, 60}});
  for (auto& p : later.phones) p.first_frame += 500, p.end_frame += 500;
  EXPECT_EQ(wanted_jaw(guide, later, 4.0), pair);
}

TEST(JawGuide, SynthesisRefusesTheJawTermWithoutTheGuide) {
  const Voice voice = chin_voice().open("fapcast_jaw_guide_synthesis.fapv");
  SynthesisOptions options;
  options.search.jaw_weight = 1.0;
  const TargetTimeline timeline = test::target_timeline({{Phone::SIL, 2}, {Phone::M, 3}, {Phone::AA, 3}});
  EXPECT_THROW((void)synthesize(voice.graph(), voice.frame_coefficients(), timeline, options), std::invalid_argument);
  const auto guide = jaw_guide_for(voice, options);
  ASSERT_TRUE(guide.has_value());
  const SynthesizedTrack track = synthesize(voice.graph(), voice.frame_coefficients(), timeline, options, &*guide);
  EXPECT_EQ(track.search.states, (std::vector<StateId>{0, 1, 2}));
  options.search.jaw_weight = 0.0;
  options.jaw_level = 0.0;
  EXPECT_FALSE(jaw_guide_for(voice, options).has_value()) << "no guide is made while neither the term nor the level wants it";
}

}  // namespace
}  // namespace fapcast
