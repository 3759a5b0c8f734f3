#include "fapcast/face/facial_expression.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <stdexcept>

#include "fapcast/face/blendshape.hpp"
#include "fapcast/core/tsv_table.hpp"

namespace fapcast {
namespace {

constexpr std::array<std::string_view, kExpressionCount> kNames{"joy",  "sadness", "anger",
                                                                "fear", "disgust", "surprise"};
constexpr std::array<Expression, kExpressionCount> kAll{Expression::joy,  Expression::sadness,
                                                        Expression::anger, Expression::fear,
                                                        Expression::disgust, Expression::surprise};

// spec/expressions.tsv, row for row (the test checks it); the rationale is in the TSV header.
constexpr std::array<ExpressionShapeRow, 55> kRecipes{{
    {Expression::joy, "mouthSmile_L", 0.9f},
    {Expression::joy, "mouthSmile_R", 0.9f},
    {Expression::joy, "cheekSquint_L", 0.6f},
    {Expression::joy, "cheekSquint_R", 0.6f},
    {Expression::joy, "eyeSquint_L", 0.3f},
    {Expression::joy, "eyeSquint_R", 0.3f},
    {Expression::joy, "mouthDimple_L", 0.2f},
    {Expression::joy, "mouthDimple_R", 0.2f},
    {Expression::sadness, "browInnerUp_L", 0.9f},
    {Expression::sadness, "browInnerUp_R", 0.9f},
    {Expression::sadness, "browDown_L", 0.3f},
    {Expression::sadness, "browDown_R", 0.3f},
    {Expression::sadness, "mouthFrown_L", 0.8f},
    {Expression::sadness, "mouthFrown_R", 0.8f},
    {Expression::sadness, "mouthShrugLower", 0.3f},
    {Expression::sadness, "eyeBlink_L", 0.15f},
    {Expression::sadness, "eyeBlink_R", 0.15f},
    {Expression::anger, "browDown_L", 1.0f},
    {Expression::anger, "browDown_R", 1.0f},
    {Expression::anger, "eyeWide_L", 0.3f},
    {Expression::anger, "eyeWide_R", 0.3f},
    {Expression::anger, "eyeSquint_L", 0.4f},
    {Expression::anger, "eyeSquint_R", 0.4f},
    {Expression::anger, "mouthPress_L", 0.6f},
    {Expression::anger, "mouthPress_R", 0.6f},
    {Expression::anger, "noseSneer_L", 0.3f},
    {Expression::anger, "noseSneer_R", 0.3f},
    {Expression::fear, "browInnerUp_L", 0.9f},
    {Expression::fear, "browInnerUp_R", 0.9f},
    {Expression::fear, "browOuterUp_L", 0.5f},
    {Expression::fear, "browOuterUp_R", 0.5f},
    {Expression::fear, "browDown_L", 0.3f},
    {Expression::fear, "browDown_R", 0.3f},
    {Expression::fear, "eyeWide_L", 0.9f},
    {Expression::fear, "eyeWide_R", 0.9f},
    {Expression::fear, "mouthStretch_L", 0.7f},
    {Expression::fear, "mouthStretch_R", 0.7f},
    {Expression::fear, "jawOpen", 0.2f},
    {Expression::disgust, "noseSneer_L", 1.0f},
    {Expression::disgust, "noseSneer_R", 1.0f},
    {Expression::disgust, "mouthUpperUp_L", 0.6f},
    {Expression::disgust, "mouthUpperUp_R", 0.6f},
    {Expression::disgust, "mouthFrown_L", 0.3f},
    {Expression::disgust, "mouthFrown_R", 0.3f},
    {Expression::disgust, "browDown_L", 0.4f},
    {Expression::disgust, "browDown_R", 0.4f},
    {Expression::disgust, "cheekSquint_L", 0.3f},
    {Expression::disgust, "cheekSquint_R", 0.3f},
    {Expression::surprise, "browInnerUp_L", 1.0f},
    {Expression::surprise, "browInnerUp_R", 1.0f},
    {Expression::surprise, "browOuterUp_L", 1.0f},
    {Expression::surprise, "browOuterUp_R", 1.0f},
    {Expression::surprise, "eyeWide_L", 1.0f},
    {Expression::surprise, "eyeWide_R", 1.0f},
    {Expression::surprise, "jawOpen", 0.4f},
}};

void check_intensity(const FacialExpression& e) {
  if (e.intensity < 0 || e.intensity > kMaxExpressionIntensity)
    throw std::invalid_argument("expression intensity " + std::to_string(e.intensity) +
                                " outside 0..63 (FAP 2 expression_intensity)");
}

}  // namespace

std::string_view expression_name(Expression expression) {
  const auto i = static_cast<std::size_t>(expression);
  if (i < 1 || i > kExpressionCount)
    throw std::invalid_argument("expression_select " + std::to_string(i) + " outside 1..6");
  return kNames[i - 1];
}

Expression expression_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return kAll[i];
  std::string message = "unknown expression '";
  message += name;
  message += "' (one of joy, sadness, anger, fear, disgust, surprise)";
  throw std::invalid_argument(message);
}

std::span<const Expression> all_expressions() { return kAll; }

FacialExpression parse_facial_expression(std::string_view text) {
  const auto colon = text.find(':');
  FacialExpression out{expression_from_name(text.substr(0, colon)), kMaxExpressionIntensity};
  if (colon == std::string_view::npos) return out;
  const auto number = text.substr(colon + 1);
  const auto [end, err] = std::from_chars(number.data(), number.data() + number.size(), out.intensity);
  if (err != std::errc{} || end != number.data() + number.size() || number.empty()) {
    std::string message = "expression intensity '";
    message += number;
    message += "' is not an integer 0..63";
    throw std::invalid_argument(message);
  }
  check_intensity(out);
  return out;
}

std::span<const ExpressionShapeRow> expression_table() { return kRecipes; }

std::vector<float> expression_shape_weights(const FaceModel& face, const FacialExpression& first,
                                            const std::optional<FacialExpression>& second) {
  std::vector<float> weights(face.expression_names.size(), 0.0f);
  const auto add = [&](const FacialExpression& e) {
    check_intensity(e);
    const float scale = static_cast<float>(e.intensity) / kMaxExpressionIntensity;
    for (const auto& row : kRecipes)
      if (row.expression == e.expression) weights[face.expression_index(row.shape)] += row.weight * scale;
  };
  add(first);
  if (second) add(*second);
  for (auto& w : weights) w = std::clamp(w, 0.0f, 1.0f);
  return weights;
}

Positions expression_displacement(const FaceModel& face, const FacialExpression& first,
                                  const std::optional<FacialExpression>& second) {
  const auto weights = expression_shape_weights(face, first, second);
  Positions out = Positions::Zero(3, face.vertex_count());
  for (std::size_t s = 0; s < weights.size(); ++s)
    if (weights[s] != 0.0f) add_scaled(out, face.expressions[s], weights[s]);
  return out;
}

std::vector<ExpressionSpecRow> read_expression_spec(const std::filesystem::path& file) {
  std::vector<ExpressionSpecRow> out;
  for (const auto& row : read_tsv(file, 3))
    out.push_back({row.fields[0], row.fields[1], tsv_float(file, row, 2)});
  return out;
}

}  // namespace fapcast
