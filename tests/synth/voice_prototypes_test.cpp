#include "fapcast/synth/voice_prototypes.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "fapcast/synth/articulation.hpp"
#include "fapcast/synth/face_model.hpp"

namespace fapcast::synth {
namespace {

const std::filesystem::path kSpecDir = std::filesystem::path(FAPCAST_SOURCE_DIR) / "spec";

std::vector<VisemeClass> all_classes() {
  std::vector<VisemeClass> out;
  for (std::size_t v = 0; v < kVisemeClassCount; ++v) out.push_back(static_cast<VisemeClass>(v));
  return out;
}

TEST(TargetPrototypes, TableAgreesWithSpec) {
  const auto spec = read_prototype_spec(kSpecDir / "prototypes.tsv");
  const auto table = target_prototype_table();
  ASSERT_EQ(spec.size(), table.size());
  for (std::size_t i = 0; i < spec.size(); ++i) {
    SCOPED_TRACE(spec[i].viseme_class + " " + spec[i].shape);
    EXPECT_EQ(spec[i].viseme_class, viseme_class_name(table[i].viseme));
    EXPECT_EQ(spec[i].shape, table[i].shape);
    EXPECT_FLOAT_EQ(spec[i].weight, table[i].weight);
  }
}

// The "articulation" rows are what the talker's own channel map gives for the class's phones'
// mean targets; detail rows add to it and say why. Every class has a recipe, every shape exists.
TEST(TargetPrototypes, RecipesFollowTheArticulationTables) {
  const FaceModel& face = ict_face_model();
  const ShapeMapper mapper(face);
  const auto spec = read_prototype_spec(kSpecDir / "prototypes.tsv");
  std::map<std::string, std::map<std::string, const PrototypeSpecRow*>> by_class;
  for (const auto& row : spec) {
    EXPECT_TRUE(by_class[row.viseme_class].emplace(row.shape, &row).second) << row.viseme_class << " " << row.shape;
    EXPECT_NO_THROW((void)face.expression_index(row.shape)) << row.shape;
    EXPECT_GT(row.weight, 0.0f);
    EXPECT_LE(row.weight, 1.0f);
    EXPECT_TRUE(row.basis == "articulation" || row.basis == "articulation+detail" || row.basis == "detail") << row.basis;
    EXPECT_EQ(row.basis == "articulation", row.why == "-") << row.viseme_class << " " << row.shape;
  }
  EXPECT_EQ(by_class.size(), kVisemeClassCount);
  for (std::size_t v = 0; v < kVisemeClassCount; ++v) {
    const auto cls = static_cast<VisemeClass>(v);
    const std::string name(viseme_class_name(cls));
    SCOPED_TRACE(name);
    std::array<float, kChannelCount> mean{};
    int phones = 0;
    for (const auto& row : kVisemeTable) {
      if (row.search_class != cls) continue;
      const auto& a = phone_articulation(row.phone == Phone::SIL ? "sil" : arpabet(row.phone));
      for (std::size_t c = 0; c < kChannelCount; ++c) mean[c] += a.target[c];
      ++phones;
    }
    for (auto& x : mean) x /= static_cast<float>(phones);
    const std::vector<float> weights = mapper(mean);
    const auto& recipe = by_class[name];
    for (std::size_t s = 0; s < weights.size(); ++s) {
      const auto it = recipe.find(face.expression_names[s]);
      const float articulation = weights[s] < 0.0005f ? 0.0f : weights[s];
      if (it == recipe.end()) {
        EXPECT_EQ(articulation, 0.0f) << face.expression_names[s] << " missing from the recipe";
      } else if (it->second->basis == "articulation") {
        EXPECT_NEAR(it->second->weight, articulation, 0.0006) << face.expression_names[s];
      } else if (it->second->basis == "articulation+detail") {
        EXPECT_GT(it->second->weight, articulation + 0.01) << face.expression_names[s];
        EXPECT_GT(articulation, 0.0f) << face.expression_names[s];
      } else {
        EXPECT_EQ(articulation, 0.0f) << face.expression_names[s] << " is a detail but articulation drives it";
      }
    }
  }
}

// k = 17 components need 17 independent directions among the 21 centred target prototypes.
TEST(TargetPrototypes, CentredRankOnTheIctFaceIsAtLeast17) {
  const Eigen::MatrixXd meshes = target_prototype_meshes(ict_face_model(), all_classes());
  EXPECT_EQ(meshes.rows(), 21);
  EXPECT_EQ(meshes.cols(), 3 * ict_face_model().vertex_count());
  EXPECT_EQ(centred_rank(meshes), 18);
  // The 17th singular value is 6e-4 of the first, the 18th 4e-4; the float32 meshes' rounding
  // noise sits at 3e-7: the directions are real, not rounding artefacts.
  EXPECT_GE(centred_rank(meshes, 1e-4), 17);
  // The silence prototype is near the neutral face (metres).
  const Eigen::RowVectorXd neutral =
      Eigen::Map<const Eigen::RowVectorXf>(ict_face_model().neutral_cm.data(), meshes.cols()).cast<double>() / 100.0;
  EXPECT_LT((meshes.row(0) - neutral).cwiseAbs().maxCoeff(), 0.005);
  EXPECT_GT((meshes.row(static_cast<Eigen::Index>(VisemeClass::kOpenUnrounded)) - neutral).cwiseAbs().maxCoeff(), 0.005);
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
}  // namespace fapcast::synth
