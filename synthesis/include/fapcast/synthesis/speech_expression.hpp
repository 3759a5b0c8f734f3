#pragma once
// FAP 2 expressions blended with speech (spec/synthesis.md, "Expressions with speech"): a voice's
// face as a morph basis whose directions are the k PCA components and, when an expression is
// asked for, the expression's displacement on the voice's face as one more direction. A frame is
// mean + sum_k c_k pc_k + w e: PCA reconstruction with k + 1 components, so the same basis feeds
// the PCA -> FAP step (the lips' FAPs then come from the blended face: a smile widens the mouth)
// and glTF morphing (the expression is one more morph target a player can turn off).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/face/face_model.hpp"
#include "fapcast/face/facial_expression.hpp"
#include "fapcast/voice/voice.hpp"

namespace fapcast {

// The FAP 2 field of an utterance: one expression, optionally a second (FAP 2 carries two).
struct ExpressionBlend {
  FacialExpression first;
  std::optional<FacialExpression> second;
  bool operator==(const ExpressionBlend&) const = default;
};

// "joy:40", "joy" (= 63) or "joy:40,surprise:20". Throws std::invalid_argument saying what is
// wrong: an unknown name (listing the six), an intensity outside 0..63, more than two items.
ExpressionBlend parse_expression_blend(std::string_view text);
// "joy:40" or "joy:40,surprise:20" (parse_expression_blend's inverse).
std::string expression_blend_text(const ExpressionBlend& blend);

// The blend's displacement on the voice's face: 1 x D, metres, xyz interleaved per vertex (the
// voice's layout). The ICT displacement (expression_displacement, cm) in metres, carried through
// the voice's face maps when it was re-targeted (Voice::face_maps). Throws std::invalid_argument
// when the voice's face is not `face`'s topology (D != 3 x face.vertex_count()).
RowMajorMatrixXf expression_direction_m(const Voice& voice, const FaceModel& face, const ExpressionBlend& blend);

// A voice's face as a morph basis (metres, xyz interleaved per vertex).
struct SpeechBasis {
  RowMajorMatrixXf mean;           // 1 x D: the voice's PCA mean
  RowMajorMatrixXf components;     // K x D: the k PCA components, then the expression's direction
  std::vector<std::string> names;  // K: "pc1" ... "pck", then e.g. "joy:40"
  std::optional<ExpressionBlend> expression;
  Eigen::Index pca_count() const { return components.rows() - (expression ? 1 : 0); }
};

// The voice's basis, with the expression (on ict_face_model()) as direction k + 1 when given.
SpeechBasis speech_basis(const Voice& voice, const std::optional<ExpressionBlend>& expression = {});

// F x K weights of `basis` for F synthesised PCA frames (F x k): the PCA coefficients, then the
// expression's weight 1 (its FAP 2 intensity) in every frame. Throws std::invalid_argument when
// the frames do not have basis.pca_count() columns.
Eigen::MatrixXf speech_weights(const Eigen::MatrixXf& pca_frames, const SpeechBasis& basis);

}  // namespace fapcast
