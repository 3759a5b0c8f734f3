#include "fapcast/synthesis/speech_expression.hpp"

#include <stdexcept>

namespace fapcast {
namespace {
constexpr float kMetresPerCm = 0.01f;
}

ExpressionBlend parse_expression_blend(std::string_view text) {
  const auto comma = text.find(',');
  ExpressionBlend out{parse_facial_expression(text.substr(0, comma)), std::nullopt};
  if (comma == std::string_view::npos) return out;
  const auto rest = text.substr(comma + 1);
  if (rest.find(',') != std::string_view::npos)
    throw std::invalid_argument("FAP 2 blends at most two expressions, '" + std::string(text) + "' names more");
  out.second = parse_facial_expression(rest);
  return out;
}

std::string expression_blend_text(const ExpressionBlend& blend) {
  std::string out;
  for (const auto* e : {&blend.first, blend.second ? &*blend.second : nullptr}) {
    if (e == nullptr) continue;
    if (!out.empty()) out += ',';
    out.append(expression_name(e->expression)).append(":").append(std::to_string(e->intensity));
  }
  return out;
}

RowMajorMatrixXf expression_direction_m(const Voice& voice, const FaceModel& face, const ExpressionBlend& blend) {
  const Eigen::Index n = face.vertex_count();
  if (voice.dimension() != 3 * n)
    throw std::invalid_argument("the voice's face has " + std::to_string(voice.dimension() / 3) +
                                " vertices, the expression shapes' face " + std::to_string(n) +
                                ": expressions need the ICT topology");
  const Positions generic = kMetresPerCm * expression_displacement(face, blend.first, blend.second);
  RowMajorMatrixXf out(1, 3 * n);
  Eigen::Map<Positions> on_voice(out.data(), 3, n);
  const auto maps = voice.face_maps();
  if (!maps) {
    on_voice = generic;
    return out;
  }
  for (Eigen::Index i = 0; i < n; ++i)
    on_voice.col(i) = Eigen::Map<const Eigen::Matrix<float, 3, 3, Eigen::RowMajor>>(maps->row(i).data()) * generic.col(i);
  return out;
}

SpeechBasis::SpeechBasis(const Voice& voice)
    : mean_(voice.pca_mean().data()),
      pca_(voice.pca_components().data()),
      pca_count_(voice.pca_components().rows()),
      dimension_(voice.pca_components().cols()) {
  for (Eigen::Index i = 0; i < pca_count_; ++i) names_.push_back("pc" + std::to_string(i + 1));
}

void SpeechBasis::add(const RowMajorMatrixXf& direction, std::string name) {
  if (direction.rows() != 1 || direction.cols() != dimension_)
    throw std::invalid_argument("a direction of the speech basis is 1 x " + std::to_string(dimension_) + ", not " +
                                std::to_string(direction.rows()) + " x " + std::to_string(direction.cols()));
  added_.conservativeResize(added_.rows() + 1, dimension_);
  added_.bottomRows(1) = direction;
  names_.push_back(std::move(name));
}

SpeechBasis speech_basis(const Voice& voice, const std::optional<ExpressionBlend>& expression) {
  SpeechBasis b(voice);
  if (expression) {
    b.add(expression_direction_m(voice, ict_face_model(), *expression), expression_blend_text(*expression));
    b.expression = expression;
  }
  return b;
}

Eigen::MatrixXf speech_weights(const Eigen::MatrixXf& pca_frames, const SpeechBasis& basis) {
  const Eigen::Index k = basis.pca_count();
  if (pca_frames.cols() != k)
    throw std::invalid_argument("PCA frames have " + std::to_string(pca_frames.cols()) + " columns, the voice " +
                                std::to_string(k) + " components");
  Eigen::MatrixXf w(pca_frames.rows(), basis.size());
  w.leftCols(k) = pca_frames;
  w.rightCols(basis.size() - k).setOnes();
  return w;
}

}  // namespace fapcast
