// The six FAP 2 expressions: the recipe table agrees with spec/expressions.tsv and names real ICT
// shapes; intensity scales, two expressions add, weights clamp.
#include "fapcast/face/facial_expression.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>


namespace fapcast {
namespace {

const std::filesystem::path kSpecDir = std::filesystem::path(FAPCAST_SOURCE_DIR) / "spec";

TEST(FacialExpression, TableAgreesWithSpec) {
  const auto spec = read_expression_spec(kSpecDir / "expressions.tsv");
  const auto table = expression_table();
  ASSERT_EQ(spec.size(), table.size());
  for (std::size_t i = 0; i < spec.size(); ++i) {
    SCOPED_TRACE(spec[i].expression + " " + spec[i].shape);
    EXPECT_EQ(spec[i].expression, expression_name(table[i].expression));
    EXPECT_EQ(spec[i].shape, table[i].shape);
    EXPECT_FLOAT_EQ(spec[i].weight, table[i].weight);
  }
}

TEST(FacialExpression, EveryRecipeNamesRealIctShapesOnce) {
  const FaceModel& face = ict_face_model();
  std::set<std::pair<Expression, std::string_view>> seen;
  std::map<Expression, int> rows;
  for (const auto& row : expression_table()) {
    EXPECT_NO_THROW((void)face.expression_index(row.shape)) << row.shape;
    EXPECT_TRUE(seen.insert({row.expression, row.shape}).second) << row.shape;
    EXPECT_GT(row.weight, 0.0f);
    EXPECT_LE(row.weight, 1.0f);
    ++rows[row.expression];
  }
  for (const auto e : all_expressions()) EXPECT_GE(rows[e], 3) << expression_name(e);
}

TEST(FacialExpression, ParsesNameColonIntensity) {
  EXPECT_EQ(parse_facial_expression("joy:40"), (FacialExpression{Expression::joy, 40}));
  EXPECT_EQ(parse_facial_expression("surprise"), (FacialExpression{Expression::surprise, 63}));
  EXPECT_EQ(parse_facial_expression("fear:0"), (FacialExpression{Expression::fear, 0}));
  for (const char* bad : {"joy:64", "joy:-1", "joy:", "joy:4x", "glee:10", ":10", ""})
    EXPECT_THROW(parse_facial_expression(bad), std::invalid_argument) << bad;
}

TEST(FacialExpression, IntensityScalesAndTwoExpressionsAdd) {
  const FaceModel& face = ict_face_model();
  const Positions full = expression_displacement(face, {Expression::joy, 63});
  EXPECT_GT(full.cwiseAbs().maxCoeff(), 0.1f);  // cm: visibly moves
  EXPECT_EQ(expression_displacement(face, {Expression::joy, 0}).cwiseAbs().maxCoeff(), 0.0f);
  const Positions part = expression_displacement(face, {Expression::joy, 40});
  EXPECT_LT((part - (40.0f / 63.0f) * full).cwiseAbs().maxCoeff(), 1e-5f);
  // joy and surprise share no shape: the FAP 2 blend is the sum.
  const Positions surprise = expression_displacement(face, {Expression::surprise, 20});
  const Positions both = expression_displacement(face, {Expression::joy, 40}, FacialExpression{Expression::surprise, 20});
  EXPECT_LT((both - part - surprise).cwiseAbs().maxCoeff(), 1e-5f);
  // anger and disgust both lower the brows (1 + 0.4): the weight clamps at 1.
  const auto w = expression_shape_weights(face, {Expression::anger, 63}, FacialExpression{Expression::disgust, 63});
  EXPECT_FLOAT_EQ(w[face.expression_index("browDown_L")], 1.0f);
  EXPECT_FLOAT_EQ(w[face.expression_index("noseSneer_L")], 1.0f);
  EXPECT_FLOAT_EQ(w[face.expression_index("mouthPress_L")], 0.6f);
  EXPECT_THROW(expression_shape_weights(face, {Expression::joy, 64}), std::invalid_argument);
}

// Surprise raises the brows: the vertices it moves most go up.
TEST(FacialExpression, SurpriseRaisesTheBrows) {
  const FaceModel& face = ict_face_model();
  const Positions d = expression_displacement(face, {Expression::surprise, 63});
  const auto brow = face.expressions[face.expression_index("browOuterUp_L")];
  float up = 0;
  for (const auto v : brow.vertices) up += d(1, v);
  EXPECT_GT(up / static_cast<float>(brow.vertices.size()), 0.05f);
}

}  // namespace
}  // namespace fapcast
