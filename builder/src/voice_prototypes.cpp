#include "fapcast/builder/voice_prototypes.hpp"

#include <Eigen/SVD>
#include <array>
#include <limits>
#include <stdexcept>
#include <string>

#include "fapcast/core/tsv_table.hpp"

namespace fapcast {
namespace {

// spec/prototypes.tsv (generated from spec/articulation*.tsv plus the argued details; the
// comment there says how). Order: class, then the rows of that class.
constexpr PrototypeShapeWeight kTable[] = {
    {VisemeClass::kSilence, "jawOpen", 0.02f},
    {VisemeClass::kSilence, "mouthClose", 0.017f},
    {VisemeClass::kBilabial, "jawOpen", 0.1f},
    {VisemeClass::kBilabial, "mouthClose", 0.083f},
    {VisemeClass::kBilabial, "mouthPress_L", 0.3f},
    {VisemeClass::kBilabial, "mouthPress_R", 0.3f},
    {VisemeClass::kBilabial, "mouthRollUpper", 0.15f},
    {VisemeClass::kBilabial, "mouthRollLower", 0.1f},
    {VisemeClass::kLabiodental, "jawOpen", 0.15f},
    {VisemeClass::kLabiodental, "mouthUpperUp_L", 0.15f},
    {VisemeClass::kLabiodental, "mouthUpperUp_R", 0.15f},
    {VisemeClass::kLabiodental, "mouthStretch_L", 0.04f},
    {VisemeClass::kLabiodental, "mouthStretch_R", 0.04f},
    {VisemeClass::kLabiodental, "mouthSmile_L", 0.03f},
    {VisemeClass::kLabiodental, "mouthSmile_R", 0.03f},
    {VisemeClass::kLabiodental, "mouthClose", 0.075f},
    {VisemeClass::kLabiodental, "mouthRollLower", 0.7f},
    {VisemeClass::kLabiodental, "noseSneer_L", 0.1f},
    {VisemeClass::kLabiodental, "noseSneer_R", 0.1f},
    {VisemeClass::kDental, "jawOpen", 0.2f},
    {VisemeClass::kDental, "mouthLowerDown_L", 0.25f},
    {VisemeClass::kDental, "mouthLowerDown_R", 0.25f},
    {VisemeClass::kDental, "mouthUpperUp_L", 0.1f},
    {VisemeClass::kDental, "mouthUpperUp_R", 0.1f},
    {VisemeClass::kDental, "jawForward", 0.1f},
    {VisemeClass::kAlveolar, "jawOpen", 0.2f},
    {VisemeClass::kAlveolar, "mouthLowerDown_L", 0.12f},
    {VisemeClass::kAlveolar, "mouthLowerDown_R", 0.12f},
    {VisemeClass::kAlveolar, "mouthUpperUp_L", 0.08f},
    {VisemeClass::kAlveolar, "mouthUpperUp_R", 0.08f},
    {VisemeClass::kAlveolar, "mouthPress_L", 0.1f},
    {VisemeClass::kAlveolar, "mouthPress_R", 0.1f},
    {VisemeClass::kSibilant, "jawOpen", 0.12f},
    {VisemeClass::kSibilant, "mouthLowerDown_L", 0.09f},
    {VisemeClass::kSibilant, "mouthLowerDown_R", 0.09f},
    {VisemeClass::kSibilant, "mouthUpperUp_L", 0.06f},
    {VisemeClass::kSibilant, "mouthUpperUp_R", 0.06f},
    {VisemeClass::kSibilant, "mouthStretch_L", 0.12f},
    {VisemeClass::kSibilant, "mouthStretch_R", 0.12f},
    {VisemeClass::kSibilant, "mouthSmile_L", 0.09f},
    {VisemeClass::kSibilant, "mouthSmile_R", 0.09f},
    {VisemeClass::kSibilant, "jawForward", 0.15f},
    {VisemeClass::kSibilant, "mouthDimple_L", 0.15f},
    {VisemeClass::kSibilant, "mouthDimple_R", 0.15f},
    {VisemeClass::kLateral, "jawOpen", 0.25f},
    {VisemeClass::kLateral, "mouthLowerDown_L", 0.15f},
    {VisemeClass::kLateral, "mouthLowerDown_R", 0.15f},
    {VisemeClass::kLateral, "mouthUpperUp_L", 0.16f},
    {VisemeClass::kLateral, "mouthUpperUp_R", 0.16f},
    {VisemeClass::kPostalveolar, "jawOpen", 0.15f},
    {VisemeClass::kPostalveolar, "mouthLowerDown_L", 0.12f},
    {VisemeClass::kPostalveolar, "mouthLowerDown_R", 0.12f},
    {VisemeClass::kPostalveolar, "mouthUpperUp_L", 0.08f},
    {VisemeClass::kPostalveolar, "mouthUpperUp_R", 0.08f},
    {VisemeClass::kPostalveolar, "mouthPucker", 0.36f},
    {VisemeClass::kPostalveolar, "mouthFunnel", 0.38f},
    {VisemeClass::kPostalveolar, "mouthShrugUpper", 0.2f},
    {VisemeClass::kRhotic, "jawOpen", 0.25f},
    {VisemeClass::kRhotic, "mouthLowerDown_L", 0.135f},
    {VisemeClass::kRhotic, "mouthLowerDown_R", 0.135f},
    {VisemeClass::kRhotic, "mouthUpperUp_L", 0.09f},
    {VisemeClass::kRhotic, "mouthUpperUp_R", 0.09f},
    {VisemeClass::kRhotic, "mouthPucker", 0.4f},
    {VisemeClass::kRhotic, "mouthFunnel", 0.15f},
    {VisemeClass::kRhotic, "mouthRollLower", 0.1f},
    {VisemeClass::kBack, "jawOpen", 0.287f},
    {VisemeClass::kBack, "mouthLowerDown_L", 0.165f},
    {VisemeClass::kBack, "mouthLowerDown_R", 0.165f},
    {VisemeClass::kBack, "mouthUpperUp_L", 0.11f},
    {VisemeClass::kBack, "mouthUpperUp_R", 0.11f},
    {VisemeClass::kLabialVelar, "jawOpen", 0.15f},
    {VisemeClass::kLabialVelar, "mouthLowerDown_L", 0.06f},
    {VisemeClass::kLabialVelar, "mouthLowerDown_R", 0.06f},
    {VisemeClass::kLabialVelar, "mouthUpperUp_L", 0.04f},
    {VisemeClass::kLabialVelar, "mouthUpperUp_R", 0.04f},
    {VisemeClass::kLabialVelar, "mouthPucker", 0.87f},
    {VisemeClass::kLabialVelar, "mouthFunnel", 0.36f},
    {VisemeClass::kLabialVelar, "mouthShrugLower", 0.2f},
    {VisemeClass::kLabialVelar, "mouthRollLower", 0.1f},
    {VisemeClass::kCloseFront, "jawOpen", 0.175f},
    {VisemeClass::kCloseFront, "mouthLowerDown_L", 0.135f},
    {VisemeClass::kCloseFront, "mouthLowerDown_R", 0.135f},
    {VisemeClass::kCloseFront, "mouthUpperUp_L", 0.09f},
    {VisemeClass::kCloseFront, "mouthUpperUp_R", 0.09f},
    {VisemeClass::kCloseFront, "mouthStretch_L", 0.22f},
    {VisemeClass::kCloseFront, "mouthStretch_R", 0.22f},
    {VisemeClass::kCloseFront, "mouthSmile_L", 0.165f},
    {VisemeClass::kCloseFront, "mouthSmile_R", 0.165f},
    {VisemeClass::kCloseFront, "cheekSquint_L", 0.15f},
    {VisemeClass::kCloseFront, "cheekSquint_R", 0.15f},
    {VisemeClass::kNearCloseFront, "jawOpen", 0.3f},
    {VisemeClass::kNearCloseFront, "mouthLowerDown_L", 0.18f},
    {VisemeClass::kNearCloseFront, "mouthLowerDown_R", 0.18f},
    {VisemeClass::kNearCloseFront, "mouthUpperUp_L", 0.12f},
    {VisemeClass::kNearCloseFront, "mouthUpperUp_R", 0.12f},
    {VisemeClass::kNearCloseFront, "mouthStretch_L", 0.18f},
    {VisemeClass::kNearCloseFront, "mouthStretch_R", 0.18f},
    {VisemeClass::kNearCloseFront, "mouthSmile_L", 0.135f},
    {VisemeClass::kNearCloseFront, "mouthSmile_R", 0.135f},
    {VisemeClass::kNearCloseFront, "mouthDimple_L", 0.05f},
    {VisemeClass::kNearCloseFront, "mouthDimple_R", 0.05f},
    {VisemeClass::kMidFront, "jawOpen", 0.4f},
    {VisemeClass::kMidFront, "mouthLowerDown_L", 0.225f},
    {VisemeClass::kMidFront, "mouthLowerDown_R", 0.225f},
    {VisemeClass::kMidFront, "mouthUpperUp_L", 0.15f},
    {VisemeClass::kMidFront, "mouthUpperUp_R", 0.15f},
    {VisemeClass::kMidFront, "mouthStretch_L", 0.17f},
    {VisemeClass::kMidFront, "mouthStretch_R", 0.17f},
    {VisemeClass::kMidFront, "mouthSmile_L", 0.128f},
    {VisemeClass::kMidFront, "mouthSmile_R", 0.128f},
    {VisemeClass::kMidFront, "cheekSquint_L", 0.05f},
    {VisemeClass::kMidFront, "cheekSquint_R", 0.05f},
    {VisemeClass::kOpenFront, "jawOpen", 0.6f},
    {VisemeClass::kOpenFront, "mouthLowerDown_L", 0.3f},
    {VisemeClass::kOpenFront, "mouthLowerDown_R", 0.3f},
    {VisemeClass::kOpenFront, "mouthUpperUp_L", 0.2f},
    {VisemeClass::kOpenFront, "mouthUpperUp_R", 0.2f},
    {VisemeClass::kOpenFront, "mouthStretch_L", 0.31f},
    {VisemeClass::kOpenFront, "mouthStretch_R", 0.31f},
    {VisemeClass::kOpenFront, "mouthSmile_L", 0.12f},
    {VisemeClass::kOpenFront, "mouthSmile_R", 0.12f},
    {VisemeClass::kOpenUnrounded, "jawOpen", 0.617f},
    {VisemeClass::kOpenUnrounded, "mouthLowerDown_L", 0.3f},
    {VisemeClass::kOpenUnrounded, "mouthLowerDown_R", 0.3f},
    {VisemeClass::kOpenUnrounded, "mouthUpperUp_L", 0.2f},
    {VisemeClass::kOpenUnrounded, "mouthUpperUp_R", 0.2f},
    {VisemeClass::kOpenUnrounded, "mouthStretch_L", 0.067f},
    {VisemeClass::kOpenUnrounded, "mouthStretch_R", 0.067f},
    {VisemeClass::kOpenUnrounded, "mouthSmile_L", 0.05f},
    {VisemeClass::kOpenUnrounded, "mouthSmile_R", 0.05f},
    {VisemeClass::kOpenUnrounded, "mouthFrown_L", 0.1f},
    {VisemeClass::kOpenUnrounded, "mouthFrown_R", 0.1f},
    {VisemeClass::kOpenMidRounded, "jawOpen", 0.55f},
    {VisemeClass::kOpenMidRounded, "mouthLowerDown_L", 0.27f},
    {VisemeClass::kOpenMidRounded, "mouthLowerDown_R", 0.27f},
    {VisemeClass::kOpenMidRounded, "mouthUpperUp_L", 0.18f},
    {VisemeClass::kOpenMidRounded, "mouthUpperUp_R", 0.18f},
    {VisemeClass::kOpenMidRounded, "mouthPucker", 0.42f},
    {VisemeClass::kOpenMidRounded, "mouthFunnel", 0.36f},
    {VisemeClass::kMidRounded, "jawOpen", 0.45f},
    {VisemeClass::kMidRounded, "mouthLowerDown_L", 0.21f},
    {VisemeClass::kMidRounded, "mouthLowerDown_R", 0.21f},
    {VisemeClass::kMidRounded, "mouthUpperUp_L", 0.14f},
    {VisemeClass::kMidRounded, "mouthUpperUp_R", 0.14f},
    {VisemeClass::kMidRounded, "mouthPucker", 0.56f},
    {VisemeClass::kMidRounded, "mouthFunnel", 0.38f},
    {VisemeClass::kNearCloseRounded, "jawOpen", 0.3f},
    {VisemeClass::kNearCloseRounded, "mouthLowerDown_L", 0.15f},
    {VisemeClass::kNearCloseRounded, "mouthLowerDown_R", 0.15f},
    {VisemeClass::kNearCloseRounded, "mouthUpperUp_L", 0.1f},
    {VisemeClass::kNearCloseRounded, "mouthUpperUp_R", 0.1f},
    {VisemeClass::kNearCloseRounded, "mouthPucker", 0.44f},
    {VisemeClass::kNearCloseRounded, "mouthFunnel", 0.32f},
    {VisemeClass::kCloseRounded, "jawOpen", 0.2f},
    {VisemeClass::kCloseRounded, "mouthLowerDown_L", 0.09f},
    {VisemeClass::kCloseRounded, "mouthLowerDown_R", 0.09f},
    {VisemeClass::kCloseRounded, "mouthUpperUp_L", 0.06f},
    {VisemeClass::kCloseRounded, "mouthUpperUp_R", 0.06f},
    {VisemeClass::kCloseRounded, "mouthPucker", 0.76f},
    {VisemeClass::kCloseRounded, "mouthFunnel", 0.38f},
    {VisemeClass::kCloseRounded, "mouthShrugLower", 0.1f},
    {VisemeClass::kOpenToRounded, "jawOpen", 0.6f},
    {VisemeClass::kOpenToRounded, "mouthLowerDown_L", 0.3f},
    {VisemeClass::kOpenToRounded, "mouthLowerDown_R", 0.3f},
    {VisemeClass::kOpenToRounded, "mouthUpperUp_L", 0.2f},
    {VisemeClass::kOpenToRounded, "mouthUpperUp_R", 0.2f},
    {VisemeClass::kOpenToRounded, "mouthPucker", 0.24f},
    {VisemeClass::kOpenToRounded, "mouthFunnel", 0.22f},
};

}  // namespace

std::span<const PrototypeShapeWeight> target_prototype_table() { return kTable; }

std::vector<PrototypeSpecRow> read_prototype_spec(const std::filesystem::path& file) {
  std::vector<PrototypeSpecRow> out;
  for (const auto& row : read_tsv(file, 5))
    out.push_back({row.fields[0], row.fields[1], tsv_float(file, row, 2), row.fields[3], row.fields[4]});
  return out;
}

Eigen::MatrixXd target_prototype_meshes(const FaceModel& face, std::span<const VisemeClass> classes) {
  const Eigen::Index n = face.vertex_count();
  Eigen::MatrixXd out(static_cast<Eigen::Index>(classes.size()), 3 * n);
  for (std::size_t c = 0; c < classes.size(); ++c) {
    Positions mesh = face.neutral_cm;
    for (const PrototypeShapeWeight& row : kTable)
      if (row.viseme == classes[c]) add_scaled(mesh, face.expressions[face.expression_index(row.shape)], row.weight);
    // Positions is 3 x N column-major: its storage is already x y z per vertex.
    out.row(static_cast<Eigen::Index>(c)) =
        Eigen::Map<const Eigen::RowVectorXf>(mesh.data(), 3 * n).cast<double>() / 100.0;
  }
  return out;
}

Eigen::Index centred_rank(const Eigen::MatrixXd& rows, double relative_tolerance) {
  if (rows.rows() < 2) return 0;
  const Eigen::MatrixXd centred = rows.rowwise() - rows.colwise().mean();
  // The rows are few (21) and long (D): their singular values are the square roots of the
  // small Gram matrix's (squaring the condition is harmless at the tolerances used here).
  const Eigen::MatrixXd gram = centred * centred.transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(gram);
  const Eigen::VectorXd s = svd.singularValues().cwiseMax(0.0).cwiseSqrt();
  if (s.size() == 0 || s(0) == 0) return 0;
  Eigen::Index rank = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s(i) > relative_tolerance * s(0)) ++rank;
  return rank;
}

std::vector<SourcePrototype> select_source_prototypes(const Eigen::MatrixXd& frames,
                                                      std::span<const PhoneState> states) {
  const Eigen::Index d = frames.rows();
  std::array<Eigen::VectorXd, kVisemeClassCount> sum;
  std::array<std::size_t, kVisemeClassCount> count{};
  for (auto& s : sum) s = Eigen::VectorXd::Zero(d);
  for (std::size_t j = 0; j < states.size(); ++j) {
    const PhoneState& s = states[j];
    if (s.frames.count == 0 ||
        static_cast<Eigen::Index>(s.frames.first) + static_cast<Eigen::Index>(s.frames.count) > frames.cols())
      throw std::invalid_argument("select_source_prototypes: state " + std::to_string(j) +
                                  " spans frames outside the " + std::to_string(frames.cols()) + " given");
    const auto v = static_cast<std::size_t>(s.viseme);
    sum[v] += frames.col(centre_frame(s));
    ++count[v];
  }
  std::array<double, kVisemeClassCount> best_distance;
  best_distance.fill(std::numeric_limits<double>::infinity());
  std::array<Eigen::Index, kVisemeClassCount> best_frame{};
  std::array<Eigen::VectorXd, kVisemeClassCount> mean;
  for (std::size_t v = 0; v < kVisemeClassCount; ++v)
    if (count[v] > 0) mean[v] = sum[v] / static_cast<double>(count[v]);
  for (const PhoneState& s : states) {
    const auto v = static_cast<std::size_t>(s.viseme);
    const Eigen::Index f = centre_frame(s);
    const double distance = (frames.col(f) - mean[v]).squaredNorm();
    if (distance < best_distance[v] || (distance == best_distance[v] && f < best_frame[v])) {
      best_distance[v] = distance;
      best_frame[v] = f;
    }
  }
  std::vector<SourcePrototype> out;
  for (std::size_t v = 0; v < kVisemeClassCount; ++v)
    if (count[v] > 0) out.push_back({static_cast<VisemeClass>(v), best_frame[v], count[v]});
  return out;
}

}  // namespace fapcast
