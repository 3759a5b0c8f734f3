#include "fapcast/eval/retarget_evaluation.hpp"

#include <array>
#include <string>

#include "fapcast/core/input_error.hpp"
#include "fapcast/face/marker_map.hpp"
#include "fapcast/capture/preprocessing.hpp"
#include "fapcast/builder/voice_corpus.hpp"

namespace fapcast {

RetargetEvaluation evaluate_retargeting(const Voice& voice, const std::filesystem::path& corpus_dir,
                                        const std::function<void(std::size_t, std::size_t)>& progress) {
  // The six lip vertices on the target face, and the voice's source head frame (cm, in
  // rigid_marker_rows() order, as preprocess_take wants it).
  std::array<std::int32_t, 6> vertices{};
  for (std::size_t i = 0; i < kLipMarkerLabels.size(); ++i) {
    bool found = false;
    for (const auto& p : voice.feature_points())
      if (p.label == kLipMarkerLabels[i]) vertices[i] = p.vertex, found = true;
    for (const auto& r : voice.rigid_markers())
      if (r.label == kLipMarkerLabels[i]) vertices[i] = r.vertex, found = true;
    if (!found)
      throw InputError({voice.file().source(), std::nullopt, std::nullopt}, "voice-feature-points",
                       "the voice has no point " + std::string(kLipMarkerLabels[i]) + " for the lip measures");
  }
  const auto sites = marker_sites();
  const auto rigid_rows = rigid_marker_rows();
  Eigen::Matrix3Xd reference(3, static_cast<Eigen::Index>(rigid_rows.size()));
  for (std::size_t i = 0; i < rigid_rows.size(); ++i) {
    bool found = false;
    for (const auto& r : voice.rigid_markers())
      if (r.label == sites[rigid_rows[i]].label) reference.col(static_cast<Eigen::Index>(i)) = 100.0 * r.source_reference_m, found = true;
    if (!found)
      throw InputError({voice.file().source(), std::nullopt, std::nullopt}, "voice-feature-points",
                       "the voice has no rigid marker " + std::string(sites[rigid_rows[i]].label));
  }

  // Only the 18 coordinates of the six points are needed: y = b + W^T phi restricted to them,
  // and the PCA rebuild mean + c^T C with c = (W C)^T phi + C^T (b - mean); phi the map's
  // responses and the lip-contact amount, W their weights (Retargeting).
  const Retargeting& map = voice.retargeting();
  const auto mean = voice.pca_mean();
  const auto components = voice.pca_components();  // k x D
  const Eigen::Index m = map.response_count(), k = components.rows();
  Eigen::MatrixXd w_sub(m, 18), c_sub(k, 18);
  Eigen::VectorXd b_sub(18), mean_sub(18);
  for (std::size_t i = 0; i < 6; ++i)
    for (Eigen::Index a = 0; a < 3; ++a) {
      const Eigen::Index col = 3 * vertices[i] + a, j = 3 * static_cast<Eigen::Index>(i) + a;
      w_sub.col(j) = map.weights().col(col);
      c_sub.col(j) = components.col(col).cast<double>();
      b_sub(j) = map.offset()(col);
      mean_sub(j) = mean(0, col);
    }
  const Eigen::MatrixXd c_full = components.transpose().cast<double>();                 // D x k
  const Eigen::MatrixXd projection = map.weights() * c_full;                             // m x k
  const Eigen::VectorXd constant = c_full.transpose() * (map.offset() - mean.row(0).transpose().cast<double>());
  const std::array<std::int32_t, 6> local{0, 1, 2, 3, 4, 5};

  const CorpusListing listing = list_corpus(corpus_dir);
  LipCurves source, retargeted, compressed;
  RetargetEvaluation out;
  for (std::size_t u = 0; u < listing.utterances.size(); ++u) {
    const CorpusTake take = read_corpus_take(listing, u);
    const PreprocessedTake stabilised = preprocess_take(take.markers, rigid_marker_rows(), reference);
    const Eigen::MatrixXd x = source_vectors_m(stabilised.frames, listing.utterances[u].markers.string());
    if (x.rows() != map.source_dimension())
      throw InputError({voice.file().source(), std::nullopt, std::nullopt}, "voice-feature-points",
                       "the voice's source vector has " + std::to_string(map.source_dimension()) + " coordinates, the corpus " +
                           std::to_string(x.rows()));
    Eigen::MatrixXf rbf_points(x.cols(), 18), pca_points(x.cols(), 18);
    for (Eigen::Index f = 0; f < x.cols(); ++f) {
      const Eigen::VectorXd phi = map.responses(x.col(f));
      rbf_points.row(f) = (b_sub + w_sub.transpose() * phi).transpose().cast<float>();
      const Eigen::VectorXd c = projection.transpose() * phi + constant;
      pca_points.row(f) = (mean_sub + c_sub.transpose() * c).transpose().cast<float>();
    }
    source.append(lip_curves(stabilised.frames));
    retargeted.append(lip_curves(rbf_points, local));
    compressed.append(lip_curves(pca_points, local));
    out.frames += x.cols();
    if (progress) progress(u + 1, listing.utterances.size());
  }
  out.utterances = listing.utterances.size();
  out.retargeted = compare_lip_curves(source, retargeted);
  out.compressed = compare_lip_curves(source, compressed);
  return out;
}

}  // namespace fapcast
