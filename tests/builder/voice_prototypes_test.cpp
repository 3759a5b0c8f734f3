#include "fapcast/builder/voice_prototypes.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "fapcast/face/face_model.hpp"
#include "fapcast/talker/coarticulation.hpp"

namespace fapcast {
namespace {

const std::filesystem::path kSpecDir = std::filesystem::path(FAPCAST_SOURCE_DIR) / "spec";

std::vector<VisemeClass> all_classes() {
  std::vector<VisemeClass> out;
  for (std::size_t v = 0; v < kVisemeClassCount; ++v) out.push_back(static_cast<VisemeClass>(v));
  return out;
}

std::vector<ChannelValues> nominal(const std::vector<VisemeClass>& classes) {
  std::vector<ChannelValues> out;
  for (const VisemeClass v : classes) out.push_back(nominal_class_channels(v));
  return out;
}

TEST(TargetPrototypes, DetailsAgreeWithSpec) {
  const auto spec = read_prototype_spec(kSpecDir / "prototypes.tsv");
  const auto table = target_prototype_details();
  ASSERT_EQ(spec.size(), table.size());
  std::set<std::pair<std::string, std::string>> seen;
  for (std::size_t i = 0; i < spec.size(); ++i) {
    SCOPED_TRACE(spec[i].viseme_class + " " + spec[i].shape);
    EXPECT_EQ(spec[i].viseme_class, viseme_class_name(table[i].viseme));
    EXPECT_EQ(spec[i].shape, table[i].shape);
    EXPECT_FLOAT_EQ(spec[i].weight, table[i].weight);
    EXPECT_GT(spec[i].weight, 0.0f);
    EXPECT_LE(spec[i].weight, 1.0f);
    EXPECT_NE(spec[i].why, "-");
    EXPECT_NO_THROW((void)ict_face_model().expression_index(spec[i].shape));
    EXPECT_TRUE(seen.emplace(spec[i].viseme_class, spec[i].shape).second) << "twice";
  }
}

// k = 17 components need 17 independent directions among the 21 centred target prototypes: at
// the classes' nominal channels (the targets) and at the realised ones alike.
TEST(TargetPrototypes, CentredRankOnTheIctFaceIsAtLeast17) {
  const Eigen::MatrixXd meshes = target_prototype_meshes(ict_face_model(), all_classes(), nominal(all_classes()));
  EXPECT_EQ(meshes.rows(), 21);
  EXPECT_EQ(meshes.cols(), 3 * ict_face_model().vertex_count());
  EXPECT_EQ(centred_rank(meshes), 18);
  // The float32 meshes' rounding noise sits at 3e-7: the 17 directions are real, not rounding
  // artefacts.
  EXPECT_GE(centred_rank(meshes, 1e-4), 17);
  // The silence prototype is near the neutral face (metres).
  const Eigen::RowVectorXd neutral =
      Eigen::Map<const Eigen::RowVectorXf>(ict_face_model().neutral_cm.data(), meshes.cols()).cast<double>() / 100.0;
  EXPECT_LT((meshes.row(0) - neutral).cwiseAbs().maxCoeff(), 0.005);
  EXPECT_GT((meshes.row(static_cast<Eigen::Index>(VisemeClass::kOpenUnrounded)) - neutral).cwiseAbs().maxCoeff(), 0.005);
  EXPECT_THROW((void)target_prototype_meshes(ict_face_model(), all_classes(), {}), std::invalid_argument);
}

// A recipe: the shape map of the channels plus the class's details, nothing else.
TEST(TargetPrototypes, RecipeIsTheShapeMapPlusTheDetails) {
  const FaceModel& face = ict_face_model();
  const ShapeMapper mapper(face);
  for (std::size_t c = 0; c < kVisemeClassCount; ++c) {
    const auto v = static_cast<VisemeClass>(c);
    SCOPED_TRACE(std::string(viseme_class_name(v)));
    const ChannelValues channels = nominal_class_channels(v);
    std::vector<float> expected = mapper(channels);
    for (const auto& d : target_prototype_details())
      if (d.viseme == v) expected[face.expression_index(d.shape)] += d.weight;
    const std::vector<float> got = target_prototype_weights(face, v, channels);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t s = 0; s < got.size(); ++s) EXPECT_FLOAT_EQ(got[s], std::min(expected[s], 1.0f)) << face.expression_names[s];
  }
}

// The realised articulation of a take: at each segment's centre frame, the channel values of the
// coarticulated take; per class their mean. /m/ between open vowels undershoots its jaw target
// (the vowels pull it open) and its closure stays near 1; the vowel falls short of its targets.
TEST(RealisedArticulation, MeansTheChannelsAtTheCentreFrames) {
  RealisedArticulation r;
  const std::vector<Phone> phones{Phone::SIL, Phone::AA, Phone::M, Phone::AA, Phone::SIL};
  const std::vector<FrameSpan> spans{{0, 10}, {10, 12}, {22, 5}, {27, 12}, {39, 10}};
  r.add_take(phones, spans);
  PhoneTimeline timeline{SampleRate{60}, {}};
  for (std::size_t s = 0; s < phones.size(); ++s)
    timeline.phones.push_back({phones[s], spans[s].first, std::int64_t{spans[s].first} + spans[s].count});
  const auto at = [&](std::size_t s) {
    return channel_values_at(timeline, static_cast<double>(spans[s].first + spans[s].count / 2) / 60.0);
  };
  EXPECT_EQ(r.count(VisemeClass::kOpenUnrounded), 2u);
  EXPECT_EQ(r.count(VisemeClass::kBilabial), 1u);
  EXPECT_EQ(r.count(VisemeClass::kSilence), 2u);
  EXPECT_EQ(r.count(VisemeClass::kLabialVelar), 0u);
  const ChannelValues vowel = r.mean(VisemeClass::kOpenUnrounded);
  const ChannelValues m = r.mean(VisemeClass::kBilabial);
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    EXPECT_NEAR(vowel[c], 0.5f * (at(1)[c] + at(3)[c]), 1e-6f) << c;
    EXPECT_NEAR(m[c], at(2)[c], 1e-6f) << c;
  }
  const auto jaw = static_cast<std::size_t>(Channel::jaw);
  EXPECT_GT(m[jaw], phone_articulation(Phone::M).target[jaw]);
  EXPECT_LT(vowel[jaw], phone_articulation(Phone::AA).target[jaw]);
  EXPECT_GT(m[static_cast<std::size_t>(Channel::closure)], 0.9f);
  EXPECT_THROW((void)r.mean(VisemeClass::kLabialVelar), std::invalid_argument);
  EXPECT_THROW(r.add_take(phones, std::span(spans).first(2)), std::invalid_argument);
}

TEST(TargetPrototypes, CentredRankCountsIndependentDirections) {
  Eigen::MatrixXd rows(4, 3);
  rows << 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 0;  // on a line: rank 1
  EXPECT_EQ(centred_rank(rows), 1);
  rows.row(3) << 0, 1, 0;
  EXPECT_EQ(centred_rank(rows), 2);
  EXPECT_EQ(centred_rank(Eigen::MatrixXd::Ones(3, 5)), 0);
}

PhoneState state(std::uint32_t utterance, VisemeClass v, std::uint32_t first, std::uint32_t count) {
  return {utterance, v, {first, count}};
}

// The rule: per class, the centre frame of its states nearest the mean of those centre frames.
TEST(SourcePrototypes, PickTheCentreFrameNearestTheClassMean) {
  Eigen::MatrixXd frames = Eigen::MatrixXd::Zero(2, 12);
  // Bilabial states centred on frames 1, 5 and 9 with x = 0, 1, 5: the mean is 2, frame 5 wins.
  frames(0, 1) = 0;
  frames(0, 5) = 1;
  frames(0, 9) = 5;
  frames.col(0).setConstant(100);  // not a centre frame: ignored although it is extreme
  // Silence: two states with the same centre value: the earlier frame wins the tie.
  frames(1, 3) = 1;
  frames(1, 11) = 1;
  const std::vector<PhoneState> states = {
      state(0, VisemeClass::kBilabial, 0, 3),  // centre 0 + 3/2 = 1
      state(0, VisemeClass::kSilence, 3, 1),   // centre 3
      state(0, VisemeClass::kBilabial, 4, 2),  // centre 5
      state(1, VisemeClass::kBilabial, 8, 2),  // centre 9
      state(1, VisemeClass::kSilence, 10, 2),  // centre 11
  };
  const auto chosen = select_source_prototypes(frames, states);
  ASSERT_EQ(chosen.size(), 2u);  // classes absent from the corpus get no prototype
  EXPECT_EQ(chosen[0].viseme, VisemeClass::kSilence);
  EXPECT_EQ(chosen[0].frame, 3);
  EXPECT_EQ(chosen[0].candidates, 2u);
  EXPECT_EQ(chosen[1].viseme, VisemeClass::kBilabial);
  EXPECT_EQ(chosen[1].frame, 5);
  EXPECT_EQ(chosen[1].candidates, 3u);
}

TEST(SourcePrototypes, RefuseSpansOutsideTheFrames) {
  const Eigen::MatrixXd frames = Eigen::MatrixXd::Zero(3, 4);
  EXPECT_THROW((void)select_source_prototypes(frames, std::vector{state(0, VisemeClass::kSilence, 2, 3)}), std::invalid_argument);
  EXPECT_THROW((void)select_source_prototypes(frames, std::vector{state(0, VisemeClass::kSilence, 1, 0)}), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
