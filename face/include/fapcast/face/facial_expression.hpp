#pragma once
// The six universal expressions of MPEG-4 FAP 2 (joy, sadness, anger, fear, disgust, surprise)
// as recipes of ICT expression-shape weights (spec/expressions.tsv), and the displacement of a
// face for one expression or a FAP 2 blend of two, each at an intensity 0..63.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/face/face_model.hpp"
#include "fapcast/face/mesh_types.hpp"

namespace fapcast {

// FAP 2 expression_select values 1..6 (0 = none is "no expression", not an Expression).
enum class Expression : std::uint8_t { joy = 1, sadness, anger, fear, disgust, surprise };
inline constexpr std::size_t kExpressionCount = 6;
// expression_intensity: 0 (none) to 63 (the recipe at full weight), inclusive.
inline constexpr int kMaxExpressionIntensity = 63;

// "joy", "sadness" ... as in spec/expressions.tsv.
std::string_view expression_name(Expression expression);
// Inverse of expression_name; throws std::invalid_argument listing the six names.
Expression expression_from_name(std::string_view name);
// The six, in FAP 2 order.
std::span<const Expression> all_expressions();

// One expression at an intensity (FAP 2's expression_select / expression_intensity pair).
struct FacialExpression {
  Expression expression = Expression::joy;
  int intensity = kMaxExpressionIntensity;  // 0..63
  bool operator==(const FacialExpression&) const = default;
};
// "joy:40" or "joy" (= intensity 63); throws std::invalid_argument saying what is wrong.
FacialExpression parse_facial_expression(std::string_view text);

// One row of the recipe table: shape weight at intensity 63.
struct ExpressionShapeRow {
  Expression expression;
  std::string_view shape;  // ICT expression name
  float weight;            // (0, 1]
};
// The whole table, expression-major in FAP 2 order (spec/expressions.tsv row for row).
std::span<const ExpressionShapeRow> expression_table();

// ICT shape weights (one per face.expression_names entry) for up to two expressions:
// sum over both of recipe weight * intensity / 63, clamped to [0, 1] (FAP 2 blends the two).
// Throws std::invalid_argument for an intensity outside 0..63, std::out_of_range when the face
// lacks a shape a recipe names.
std::vector<float> expression_shape_weights(const FaceModel& face, const FacialExpression& first,
                                            const std::optional<FacialExpression>& second = {});

// The 3 x N displacement (cm) of face.neutral_cm that the weights above produce.
Positions expression_displacement(const FaceModel& face, const FacialExpression& first,
                                  const std::optional<FacialExpression>& second = {});

// spec/expressions.tsv as read from disk (3 columns: expression, shape, weight).
struct ExpressionSpecRow {
  std::string expression, shape;
  float weight;
};
std::vector<ExpressionSpecRow> read_expression_spec(const std::filesystem::path& file);

}  // namespace fapcast
