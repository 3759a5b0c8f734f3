// The jaw guide of the search's jaw term (synthesis/jaw_guide.hpp): each state's recorded chin
// opening and each phone's mean in units of the speech states' spread, and the wanted opening
// of a target timeline.
#include "fapcast/synthesis/jaw_guide.hpp"
#include "fapcast/synthesis/synthesis.hpp"

#include "fapcast/core/file_io.hpp"
#include "support/tiny_voice.hpp"

#include <gtest/gtest.h>

#include <filesystem>

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

Voice open_voice(const test::TinyVoice& tiny, const std::string& name) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / name;
  write_file_atomically(file, tiny.bytes());
  return Voice::open(file);
}

// `frames` frames of each phone in turn.
TargetTimeline timeline_of(std::initializer_list<std::pair<Phone, std::int64_t>> phones) {
  TargetTimeline t;
  t.sample_rate = SampleRate{16000};
  std::int64_t at = 0;
  for (const auto& [phone, frames] : phones) {
    t.phones.push_back({search_viseme(phone), at, at + frames, false});
    t.phone_of.push_back(phone);
    at += frames;
  }
  return t;
}

TEST(JawGuide, MeasuresTheChinInUnitsOfTheSpeechStatesSpread) {
  const Voice voice = open_voice(chin_voice(), "fapcast_jaw_guide.fapv");
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
  const Voice no_chin = open_voice(chin_voice("2.2"), "fapcast_jaw_guide_no_chin.fapv");
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
  const Voice still_voice = open_voice(still, "fapcast_jaw_guide_still.fapv");
  try {
    (void)make_jaw_guide(still_voice);
    FAIL() << "a voice whose chin does not move was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "jaw-guide") << e.what();
  }
}

TEST(JawGuide, WantsEachPhonesOpeningSmoothedAcrossItsNeighbours) {
  const Voice voice = open_voice(chin_voice(), "fapcast_jaw_guide_wanted.fapv");
  const JawGuide guide = make_jaw_guide(voice);
  // Held long, a phone reaches its own opening.
  const auto held = wanted_jaw(guide, timeline_of({{Phone::AA, 120}}), 4.0);
  ASSERT_EQ(held.size(), 1u);
  EXPECT_NEAR(held[0], 1.0f, 1e-4f);
  // Two long phones: each near its own, pulled towards the other near the boundary, symmetric.
  const auto pair = wanted_jaw(guide, timeline_of({{Phone::M, 60}, {Phone::AA, 60}}), 4.0);
  ASSERT_EQ(pair.size(), 2u);
  EXPECT_LT(pair[0], -0.8f);
  EXPECT_GT(pair[0], -1.0f);
  EXPECT_NEAR(pair[0], -pair[1], 0.02f);
  // A short M between open vowels does not close the jaw: the smoothing shares the vowels' opening.
  const auto brief = wanted_jaw(guide, timeline_of({{Phone::AA, 30}, {Phone::M, 3}, {Phone::AA, 30}}), 4.0);
  EXPECT_GT(brief[1], 0.0f);
  const auto slower = wanted_jaw(guide, timeline_of({{Phone::AA, 30}, {Phone::M, 3}, {Phone::AA, 30}}), 20.0);
  EXPECT_LT(slower[1], brief[1]) << "a higher cut-off lets the jaw follow a brief phone further";
  // A timeline that starts later gives the same (pieces of a long text).
  TargetTimeline later = timeline_of({{Phone::M, 60}, {Phone::AA, 60}});
  for (auto& p : later.phones) p.first_frame += 500, p.end_frame += 500;
  EXPECT_EQ(wanted_jaw(guide, later, 4.0), pair);
}

TEST(JawGuide, SynthesisRefusesTheJawTermWithoutTheGuide) {
  const Voice voice = open_voice(chin_voice(), "fapcast_jaw_guide_synthesis.fapv");
  SynthesisOptions options;
  options.search.jaw_weight = 1.0;
  const TargetTimeline timeline = timeline_of({{Phone::SIL, 2}, {Phone::M, 3}, {Phone::AA, 3}});
  EXPECT_THROW((void)synthesize(voice.graph(), voice.frame_coefficients(), timeline, options), std::invalid_argument);
  const auto guide = jaw_guide_for(voice, options);
  ASSERT_TRUE(guide.has_value());
  const SynthesizedTrack track = synthesize(voice.graph(), voice.frame_coefficients(), timeline, options, &*guide);
  EXPECT_EQ(track.search.states, (std::vector<StateId>{0, 1, 2}));
  options.search.jaw_weight = 0.0;
  EXPECT_FALSE(jaw_guide_for(voice, options).has_value()) << "no guide is made while the term is off";
}

}  // namespace
}  // namespace fapcast
