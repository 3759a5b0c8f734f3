// FAP 2 expressions with speech: parsing the blend, the expression as one more basis direction on
// the voice's face (carried through a re-targeted voice's face maps), and the weights.
#include "fapcast/synthesis/speech_expression.hpp"

#include <gtest/gtest.h>

#include "support/tiny_voice.hpp"

namespace fapcast {
namespace {

using fapcast::test::TinyVoice;

TEST(ExpressionBlend, ParsesOneOrTwoAndRefusesTheRest) {
  EXPECT_EQ(parse_expression_blend("joy:40"), (ExpressionBlend{{Expression::joy, 40}, std::nullopt}));
  EXPECT_EQ(parse_expression_blend("surprise"), (ExpressionBlend{{Expression::surprise, 63}, std::nullopt}));
  const auto two = parse_expression_blend("joy:40,fear:20");
  ASSERT_TRUE(two.second.has_value());
  EXPECT_EQ(*two.second, (FacialExpression{Expression::fear, 20}));
  EXPECT_EQ(expression_blend_text(two), "joy:40,fear:20");
  for (const std::string bad : {"glee:40", "joy:64", "joy:-1", "joy:4x", "joy:", "joy,fear,anger", "", "joy:40,"}) {
    SCOPED_TRACE(bad);
    EXPECT_THROW((void)parse_expression_blend(bad), std::invalid_argument);
  }
  try {
    (void)parse_expression_blend("glee:40");
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("surprise"), std::string::npos) << "lists the six names: " << e.what();
  }
}

Voice ict_wide_voice(const std::optional<RowMajorMatrixXf>& maps, const std::string& name) {
  TinyVoice t;
  t.vertices = ict_face_model().vertex_count();
  t.face_maps = maps;
  return t.open(name);
}

TEST(SpeechBasis, TheExpressionIsOneMoreDirectionOnTheVoicesFace) {
  const FaceModel& face = ict_face_model();
  const Voice voice = ict_wide_voice(std::nullopt, "fapcast_expr_voice.fapv");
  const ExpressionBlend joy{{Expression::joy, 40}, std::nullopt};
  const SpeechBasis plain = speech_basis(voice);
  EXPECT_EQ(plain.size(), 1);
  EXPECT_EQ(plain.names(), std::vector<std::string>{"pc1"});
  // The PCA part is the voice file itself, not a copy.
  EXPECT_EQ(plain.pca_components().data(), voice.pca_components().data());
  EXPECT_EQ(plain.mean().data(), voice.pca_mean().data());
  const SpeechBasis b = speech_basis(voice, joy);
  ASSERT_EQ(b.size(), 2);
  EXPECT_EQ(b.pca_count(), 1);
  EXPECT_EQ(b.names().back(), "joy:40");
  EXPECT_EQ(b.direction(0), voice.pca_components().row(0));
  const Positions want = 0.01f * expression_displacement(face, joy.first);
  const Eigen::Map<const Positions> got(b.direction(1).data(), 3, face.vertex_count());
  EXPECT_LT((got - want).cwiseAbs().maxCoeff(), 1e-9f);
  EXPECT_GT(want.cwiseAbs().maxCoeff(), 1e-3f) << "joy moves the face by millimetres";

  const Eigen::MatrixXf frames = Eigen::MatrixXf::Constant(4, 1, 0.25f);
  const Eigen::MatrixXf w = speech_weights(frames, b);
  ASSERT_EQ(w.cols(), 2);
  EXPECT_EQ(w.col(0), frames.col(0));
  EXPECT_TRUE((w.col(1).array() == 1.0f).all());
  EXPECT_THROW((void)speech_weights(Eigen::MatrixXf::Zero(4, 2), b), std::invalid_argument);

  // A re-targeted voice (face maps 2 I): the expression comes out twice as large.
  RowMajorMatrixXf maps = RowMajorMatrixXf::Zero(face.vertex_count(), 9);
  maps.col(0).setConstant(2.f);
  maps.col(4).setConstant(2.f);
  maps.col(8).setConstant(2.f);
  const Voice big = ict_wide_voice(maps, "fapcast_expr_voice_big.fapv");
  const SpeechBasis bb = speech_basis(big, joy);
  EXPECT_LT((bb.direction(1) - 2.f * b.direction(1)).cwiseAbs().maxCoeff(), 1e-9f);
}

TEST(SpeechBasis, RefusesAVoiceOfAnotherTopology) {
  const Voice voice = TinyVoice().open("fapcast_expr_tiny.fapv");  // three vertices
  EXPECT_THROW((void)speech_basis(voice, ExpressionBlend{{Expression::joy, 40}, std::nullopt}), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
