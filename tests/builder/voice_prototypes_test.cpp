#include "fapcast/builder/voice_prototypes.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "fapcast/face/face_model.hpp"

namespace fapcast {
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
}  // namespace fapcast
