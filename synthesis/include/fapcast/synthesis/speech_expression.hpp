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

// A voice's face as a morph basis (metres, xyz interleaved per vertex): the mean and K
// directions, first the voice's k PCA components, then the directions added to them (an
// expression's displacement). The mean and the components are read in place from the voice's
// mapped file, not copied (5.45 MB for the default voice): a basis is valid while its voice
// lives. The added directions are its own.
class SpeechBasis {
 public:
  SpeechBasis() = default;
  // The voice's mean and k components, named "pc1" ... "pck".
  explicit SpeechBasis(const Voice& voice);

  Eigen::Map<const RowMajorMatrixXf> mean() const { return {mean_, 1, dimension_}; }  // 1 x D
  Eigen::Map<const RowMajorMatrixXf> pca_components() const { return {pca_, pca_count_, dimension_}; }  // k x D
  const RowMajorMatrixXf& added() const { return added_; }  // (K - k) x D
  // Direction i of K, 1 x D.
  Eigen::Map<const Eigen::RowVectorXf> direction(Eigen::Index i) const {
    return {i < pca_count_ ? pca_ + i * dimension_ : added_.row(i - pca_count_).data(), dimension_};
  }
  Eigen::Index size() const { return pca_count_ + added_.rows(); }  // K
  Eigen::Index pca_count() const { return pca_count_; }               // k
  Eigen::Index dimension() const { return dimension_; }               // D
  const std::vector<std::string>& names() const { return names_; }   // K: "pc1" ... "pck", then the added
  // Appends `direction` (1 x D) as direction K + 1, named `name`. Throws std::invalid_argument
  // when it is not 1 x D.
  void add(const RowMajorMatrixXf& direction, std::string name);

  std::optional<ExpressionBlend> expression;  // the expression whose direction was added, if any

 private:
  const float* mean_ = nullptr;  // in the voice's file
  const float* pca_ = nullptr;   // in the voice's file, k x D row-major
  Eigen::Index pca_count_ = 0;
  Eigen::Index dimension_ = 0;
  RowMajorMatrixXf added_;
  std::vector<std::string> names_;
};

// The voice's basis, with the expression (on ict_face_model()) as direction k + 1 when given.
SpeechBasis speech_basis(const Voice& voice, const std::optional<ExpressionBlend>& expression = {});

// F x K weights of `basis` for F synthesised PCA frames (F x k): the PCA coefficients, then
// weight 1 for each added direction (an expression at its FAP 2 intensity) in every frame. Throws std::invalid_argument when
// the frames do not have basis.pca_count() columns.
Eigen::MatrixXf speech_weights(const Eigen::MatrixXf& pca_frames, const SpeechBasis& basis);

}  // namespace fapcast
