// The jaw's level (synthesis/jaw_level.hpp): the jaw's own move (the mandible lowers, the lips keep
// their shape) and the levelling of synthesised frames' slow jaw towards the wanted one.
#include "fapcast/synthesis/jaw_level.hpp"
#include "fapcast/synthesis/synthesis.hpp"

#include "support/target_timeline.hpp"
#include "support/tiny_voice.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

using V = VisemeClass;

// Vertices of the hand-made face: the chin, the lips, the front of the mandible.
enum Vertex : Eigen::Index { kChin, kUpperLip, kLowerLip, kLeftCorner, kRightCorner, kChinBoss, kChinLeft, kChinRight, kVertices };
constexpr Eigen::Index kK = 12;

Eigen::Index coordinate(Eigen::Index vertex, int axis) { return 3 * vertex + axis; }

// Components, metres per unit: 0 opens the jaw as a face does (the mandible 1 mm down, the lower
// lip 0.8 mm and the corners 0.4 mm with it), 1 raises the lower lip, 2 the corners, 3 moves the
// chin's skin alone; 4-11 each move one other coordinate of the lips or the chin boss.
RowMajorMatrixXf components() {
  RowMajorMatrixXf c = RowMajorMatrixXf::Zero(kK, 3 * kVertices);
  for (const Eigen::Index v : {kChin, kChinBoss, kChinLeft, kChinRight}) c(0, coordinate(v, 1)) = -0.001f;
  c(0, coordinate(kLowerLip, 1)) = -0.0008f;
  c(0, coordinate(kLeftCorner, 1)) = c(0, coordinate(kRightCorner, 1)) = -0.0004f;
  c(1, coordinate(kLowerLip, 1)) = 0.001f;
  c(2, coordinate(kLeftCorner, 1)) = c(2, coordinate(kRightCorner, 1)) = 0.001f;
  c(3, coordinate(kChin, 1)) = -0.001f;
  const std::pair<Eigen::Index, int> others[] = {{kUpperLip, 1}, {kUpperLip, 2}, {kLowerLip, 2}, {kLeftCorner, 0},
                                                 {kRightCorner, 0}, {kChinBoss, 2}, {kUpperLip, 0}, {kLowerLip, 0}};
  for (std::size_t i = 0; i < 8; ++i) c(static_cast<Eigen::Index>(4 + i), coordinate(others[i].first, others[i].second)) = 0.001f;
  return c;
}

// One take: rest, M (jaw nearly closed), AA (open); component 0 carries the jaw. With `lips`
// false the voice has the chin but no lip feature points.
test::TinyVoice jaw_voice(bool lips = true) {
  test::TinyVoice tiny;
  tiny.vertices = kVertices;
  tiny.components = kK;
  tiny.pca_components = components();
  RowMajorMatrixXf variances = RowMajorMatrixXf::Constant(1, kK, 1.0f);
  variances(0, 0) = 4.0f;
  tiny.pca_variances = variances;
  tiny.coefficients = RowMajorMatrixXf::Zero(5, kK);
  tiny.coefficients(1, 0) = tiny.coefficients(2, 0) = -1.0f;
  tiny.coefficients(3, 0) = tiny.coefficients(4, 0) = 3.0f;
  tiny.coefficients(3, 1) = 0.5f;  // the lower lip's own part of the vowel
  tiny.graph.utterances = {{0, 5}};
  tiny.graph.frame_count = 5;
  tiny.graph.states = {{0, V::kSilence, {0, 1}}, {0, V::kBilabial, {1, 2}}, {0, V::kOpenUnrounded, {3, 2}}};
  tiny.graph.phones = {Phone::SIL, Phone::M, Phone::AA};
  std::vector<VoiceFeaturePoint> points = {{"2.1", kChin, {0.0, -0.06, 0.08}},
                                           {"2.10", kChinBoss, {0.0, -0.05, 0.09}},
                                           {"2.11", kChinLeft, {0.02, -0.055, 0.08}},
                                           {"2.12", kChinRight, {-0.02, -0.055, 0.08}}};
  if (lips)
    for (const VoiceFeaturePoint& p : std::vector<VoiceFeaturePoint>{{"8.1", kUpperLip, {0.0, -0.02, 0.1}},
                                                                     {"8.2", kLowerLip, {0.0, -0.03, 0.1}},
                                                                     {"8.3", kLeftCorner, {0.025, -0.025, 0.09}},
                                                                     {"8.4", kRightCorner, {-0.025, -0.025, 0.09}}})
      points.push_back(p);
  const std::vector<VoiceRigidMarker> rigid = {{"H.temple_l", 0, {0.07, 0.03, 0.0}, {0.07, 0.03, 0.01}},
                                               {"H.temple_r", 1, {-0.07, 0.03, 0.0}, {-0.07, 0.03, 0.01}},
                                               {"H.nose_bridge", 2, {0.0, 0.04, 0.09}, {0.0, 0.04, 0.1}}};
  tiny.feature_points = voice_feature_points_json(points, rigid);
  tiny.source_points = static_cast<Eigen::Index>(points.size());
  return tiny;
}

// The coordinate's change made by coefficient change `c`.
double moved(const Eigen::RowVectorXf& c, Eigen::Index vertex, int axis) {
  return static_cast<double>(c.dot(components().col(coordinate(vertex, axis))));
}

TEST(JawLevel, TheJawsMoveLowersTheMandibleAndHoldsTheLips) {
  const Voice voice = jaw_voice().open("fapcast_jaw_level_move.fapv");
  const JawGuide guide = make_jaw_guide(voice);
  ASSERT_EQ(guide.jaw_move.size(), static_cast<std::size_t>(kK));
  const Eigen::RowVectorXf move = Eigen::Map<const Eigen::RowVectorXf>(guide.jaw_move.data(), kK);
  const double spread_m = guide.spread_mm / 1000.0;
  // The mandible's front goes down by one spread, all of it: the chin's skin alone (component 3)
  // would move the chin but not the bone.
  for (const Eigen::Index v : {kChin, kChinBoss, kChinLeft, kChinRight}) EXPECT_NEAR(moved(move, v, 1), -spread_m, 1e-9) << v;
  EXPECT_NEAR(move[3], 0.0f, 1e-6f);
  // The lips keep their heights, their protrusion and the mouth's width: the lower lip and the
  // corners rise against the jaw that carries them down (components 1 and 2).
  for (const Eigen::Index v : {kUpperLip, kLowerLip, kLeftCorner, kRightCorner}) EXPECT_NEAR(moved(move, v, 1), 0.0, 1e-9) << v;
  for (const Eigen::Index v : {kUpperLip, kLowerLip}) EXPECT_NEAR(moved(move, v, 2), 0.0, 1e-9) << v;
  EXPECT_NEAR(moved(move, kLeftCorner, 0) - moved(move, kRightCorner, 0), 0.0, 1e-9);
  EXPECT_NEAR(move[1], 0.8f * move[0], 1e-6f);
  EXPECT_NEAR(move[2], 0.4f * move[0], 1e-6f);
  // One unit of opening, as the guide measures it.
  EXPECT_NEAR(frame_opening(guide, move) - frame_opening(guide, Eigen::RowVectorXf::Zero(kK)), 1.0, 1e-5);
  // Without the lips' feature points the move is not made (the guide still is).
  const JawGuide lipless = make_jaw_guide(jaw_voice(false).open("fapcast_jaw_level_lipless.fapv"));
  EXPECT_TRUE(lipless.jaw_move.empty());
  EXPECT_FALSE(lipless.state_opening.empty());
}

TEST(JawLevel, LevellingGivesStillFramesTheWantedJawAndKeepsTheLips) {
  const Voice voice = jaw_voice().open("fapcast_jaw_level_frames.fapv");
  const JawGuide guide = make_jaw_guide(voice);
  const TargetTimeline timeline = test::target_timeline({{Phone::SIL, 20}, {Phone::M, 20}, {Phone::AA, 30}, {Phone::SIL, 20}});
  Eigen::MatrixXf still = Eigen::MatrixXf::Zero(90, kK);
  still.col(7).setConstant(0.5f);  // some lip posture (the upper lip forward) to be kept
  const std::vector<double> wanted = wanted_jaw_frames(guide, timeline, 4.0);
  ASSERT_EQ(wanted.size(), 90u);
  for (const double strength : {0.0, 0.5, 1.0}) {
    Eigen::MatrixXf frames = still;
    level_jaw(guide, timeline, frames, 4.0, strength);
    for (Eigen::Index n = 0; n < frames.rows(); ++n) {
      const double before = frame_opening(guide, still.row(n));
      // A still face has no fast jaw: its slow jaw is all of it, and moves `strength` of the way.
      EXPECT_NEAR(frame_opening(guide, frames.row(n)), before + strength * (wanted[static_cast<std::size_t>(n)] - before), 1e-4)
          << "frame " << n << ", strength " << strength;
      const Eigen::RowVectorXf change = frames.row(n) - still.row(n);
      for (const Eigen::Index v : {kUpperLip, kLowerLip}) {
        EXPECT_NEAR(moved(change, v, 1), 0.0, 1e-9);
        EXPECT_NEAR(moved(change, v, 2), 0.0, 1e-9);
      }
    }
  }
  // The jaw opens for the AA and closes for the M and the rests.
  Eigen::MatrixXf frames = still;
  level_jaw(guide, timeline, frames, 4.0, 1.0);
  EXPECT_GT(frame_opening(guide, frames.row(55)), frame_opening(guide, frames.row(30)) + 1.0);
}

TEST(JawLevel, KeepsTheUnitsFastJaw) {
  const Voice voice = jaw_voice().open("fapcast_jaw_level_fast.fapv");
  const JawGuide guide = make_jaw_guide(voice);
  const TargetTimeline timeline = test::target_timeline({{Phone::AA, 120}});
  // A jaw that flutters at 15 Hz about the wanted opening: far above the cut-off, it stays.
  Eigen::MatrixXf frames = Eigen::MatrixXf::Zero(120, kK);
  const double aa = guide.phone_opening[static_cast<std::size_t>(Phone::AA)];
  const Eigen::RowVectorXf move = Eigen::Map<const Eigen::RowVectorXf>(guide.jaw_move.data(), kK);
  for (Eigen::Index n = 0; n < 120; ++n)
    frames.row(n) = static_cast<float>(aa + 0.5 * std::sin(2 * 3.14159265358979 * 15.0 * static_cast<double>(n) / 60.0) -
                                       frame_opening(guide, Eigen::RowVectorXf::Zero(kK))) *
                    move;
  Eigen::MatrixXf levelled = frames;
  level_jaw(guide, timeline, levelled, 4.0, 1.0);
  for (Eigen::Index n = 20; n < 100; ++n)  // away from the ends' padding
    EXPECT_NEAR(frame_opening(guide, levelled.row(n)), frame_opening(guide, frames.row(n)), 0.02) << n;
}

TEST(JawLevel, RefusesBadStrengthsAndFramesOfAnotherShape) {
  const Voice voice = jaw_voice().open("fapcast_jaw_level_bad.fapv");
  const JawGuide guide = make_jaw_guide(voice);
  const TargetTimeline timeline = test::target_timeline({{Phone::M, 10}, {Phone::AA, 10}});
  Eigen::MatrixXf frames = Eigen::MatrixXf::Zero(20, kK);
  EXPECT_THROW(level_jaw(guide, timeline, frames, 4.0, 1.5), std::invalid_argument);
  EXPECT_THROW(level_jaw(guide, timeline, frames, 4.0, -0.1), std::invalid_argument);
  Eigen::MatrixXf short_frames = Eigen::MatrixXf::Zero(19, kK);
  EXPECT_THROW(level_jaw(guide, timeline, short_frames, 4.0, 0.5), std::invalid_argument);
  Eigen::MatrixXf narrow = Eigen::MatrixXf::Zero(20, kK - 1);
  EXPECT_THROW(level_jaw(guide, timeline, narrow, 4.0, 0.5), std::invalid_argument);
  EXPECT_TRUE(frames.isZero()) << "a refusal changes nothing";
}

TEST(JawLevel, SynthesisLevelsTheJawWhenAskedAndTheVoiceHasAChin) {
  const Voice voice = jaw_voice().open("fapcast_jaw_level_synthesis.fapv");
  const TargetTimeline timeline = test::target_timeline({{Phone::SIL, 6}, {Phone::M, 6}, {Phone::AA, 12}, {Phone::SIL, 6}});
  const SynthesisOptions shipped;
  EXPECT_EQ(shipped.jaw_level, 0.0) << "off by default: the paper's units as recorded";
  EXPECT_FALSE(jaw_guide_for(voice, shipped).has_value());
  const SynthesizedTrack recorded = synthesize(voice.graph(), voice.frame_coefficients(), timeline, shipped);
  EXPECT_FALSE(recorded.jaw_levelled);
  SynthesisOptions level = shipped;
  level.jaw_level = 0.8;
  const auto guide = jaw_guide_for(voice, level);
  ASSERT_TRUE(guide.has_value()) << "levelling makes the guide";
  const SynthesizedTrack levelled = synthesize(voice.graph(), voice.frame_coefficients(), timeline, level, &*guide);
  EXPECT_TRUE(levelled.jaw_levelled);
  EXPECT_EQ(recorded.search.states, levelled.search.states) << "levelling follows the search, it does not change it";
  EXPECT_FALSE(recorded.pca_frames.isApprox(levelled.pca_frames));
  Eigen::MatrixXf expected = recorded.pca_frames;
  level_jaw(*guide, levelled.timeline, expected, level.jaw_cutoff_hz, level.jaw_level);
  EXPECT_EQ(levelled.pca_frames, expected);
  // The voice's own overload makes the guide itself: the same track.
  const SynthesizedTrack by_voice =
      synthesize(voice, std::vector<TimedPhone>{{Phone::SIL, 0, 1600}, {Phone::M, 1600, 3200}, {Phone::AA, 3200, 6400}},
                 SampleRate{16000}, 6400, level);
  EXPECT_TRUE(by_voice.jaw_levelled);
  const auto placed = place_on_voice_grid(
      std::vector<TimedPhone>{{Phone::SIL, 0, 1600}, {Phone::M, 1600, 3200}, {Phone::AA, 3200, 6400}}, SampleRate{16000}, 6400, "t");
  EXPECT_EQ(by_voice.pca_frames, synthesize(voice.graph(), voice.frame_coefficients(), placed, level, &*guide).pca_frames);
  // A voice without the lips' feature points is not levelled, and the track says so.
  const Voice lipless = jaw_voice(false).open("fapcast_jaw_level_synthesis_lipless.fapv");
  const auto lipless_guide = jaw_guide_for(lipless, level);
  ASSERT_TRUE(lipless_guide.has_value());
  EXPECT_FALSE(synthesize(lipless.graph(), lipless.frame_coefficients(), timeline, level, &*lipless_guide).jaw_levelled);
}

}  // namespace
}  // namespace fapcast
