#include "fapcast/eval/synthesis_score.hpp"

#include "fapcast/face/marker_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fapcast {
namespace {

bool is_lip_point(const std::string& label) {
  for (const auto& site : marker_sites())
    if (site.label == label) return site.role == MarkerRole::inner_lip || site.role == MarkerRole::outer_lip;
  return false;
}

// The chin's drop below the temples' midpoint along +y, per frame of `tracks` (frames x 3V).
void append_jaw(const Eigen::Ref<const Eigen::MatrixXf>& tracks, const EvaluationPoints& points,
                std::vector<double>& out) {
  const auto y = [](std::size_t point) { return 3 * static_cast<Eigen::Index>(point) + 1; };
  const auto left = static_cast<std::size_t>(points.lip_measure[4]), right = static_cast<std::size_t>(points.lip_measure[5]);
  for (Eigen::Index f = 0; f < tracks.rows(); ++f) {
    const double temples = 0.5 * (double{tracks(f, y(left))} + double{tracks(f, y(right))});
    out.push_back(temples - double{tracks(f, y(*points.chin))});
  }
}

void check_tracks(const Eigen::MatrixXf& tracks, std::size_t vertices, const char* which) {
  if (static_cast<std::size_t>(tracks.cols()) != 3 * vertices)
    throw std::invalid_argument(std::string("synthesis score: ") + which + " tracks have " +
                                std::to_string(tracks.cols()) + " columns, expected " +
                                std::to_string(3 * vertices));
}

}  // namespace

std::array<std::int32_t, 2> ict_temple_vertices() {
  return {marker_sites()[marker_row("H.temple_l")].vertex, marker_sites()[marker_row("H.temple_r")].vertex};
}

EvaluationPoints evaluation_points(std::span<const std::string> labels,
                                   std::span<const std::int32_t> vertices,
                                   std::array<std::int32_t, 2> temple_vertices) {
  if (labels.size() != vertices.size())
    throw std::invalid_argument("evaluation points: " + std::to_string(labels.size()) + " labels for " +
                                std::to_string(vertices.size()) + " vertices");
  EvaluationPoints p;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (std::find(p.labels.begin(), p.labels.end(), labels[i]) != p.labels.end())
      throw std::invalid_argument("evaluation points: feature point " + labels[i] + " appears twice");
    p.labels.push_back(labels[i]);
    p.vertices.push_back(vertices[i]);
    p.feature_points.push_back(i);
    if (is_lip_point(labels[i])) p.lip_points.push_back(i);
    if (labels[i] == "2.1") p.chin = i;
  }
  p.labels.emplace_back("H.temple_l");
  p.vertices.push_back(temple_vertices[0]);
  p.labels.emplace_back("H.temple_r");
  p.vertices.push_back(temple_vertices[1]);
  for (std::size_t i = 0; i < kLipMarkerLabels.size(); ++i) {
    const auto it = std::find(p.labels.begin(), p.labels.end(), kLipMarkerLabels[i]);
    if (it == p.labels.end())
      throw std::invalid_argument("evaluation points: the lip measures need feature point " +
                                  std::string(kLipMarkerLabels[i]) + ", which the face does not have");
    p.lip_measure[i] = static_cast<std::int32_t>(it - p.labels.begin());
  }
  return p;
}

Eigen::MatrixXf vertex_tracks(const Eigen::Ref<const RowMajorMatrixXf>& mean,
                              const Eigen::Ref<const RowMajorMatrixXf>& components,
                              const Eigen::MatrixXf& coefficients,
                              std::span<const std::int32_t> vertices) {
  if (mean.rows() != 1 || components.cols() != mean.cols() || coefficients.cols() != components.rows())
    throw std::invalid_argument("vertex tracks: mean 1 x D, components k x D and coefficients "
                                "frames x k do not agree");
  // Gather the 3V columns once (mean and components), then one small product.
  const auto V = static_cast<Eigen::Index>(vertices.size());
  Eigen::RowVectorXf m(3 * V);
  Eigen::MatrixXf c(components.rows(), 3 * V);
  for (Eigen::Index i = 0; i < V; ++i) {
    const Eigen::Index v = vertices[static_cast<std::size_t>(i)];
    if (v < 0 || 3 * v + 2 >= mean.cols())
      throw std::invalid_argument("vertex tracks: vertex " + std::to_string(v) + " is outside the mesh");
    m.segment<3>(3 * i) = mean.block<1, 3>(0, 3 * v);
    c.middleCols<3>(3 * i) = components.middleCols<3>(3 * v);
  }
  return (coefficients * c).rowwise() + m;
}

Eigen::MatrixXf vertex_tracks(const Retargeting& map, const Eigen::MatrixXd& sources,
                              std::span<const std::int32_t> vertices) {
  if (sources.rows() != map.source_dimension())
    throw std::invalid_argument("vertex tracks: source frames have " + std::to_string(sources.rows()) +
                                " coordinates, the map expects " + std::to_string(map.source_dimension()));
  const auto V = static_cast<Eigen::Index>(vertices.size());
  Eigen::MatrixXd w(map.response_count(), 3 * V);
  Eigen::RowVectorXd b(3 * V);
  for (Eigen::Index i = 0; i < V; ++i) {
    const Eigen::Index v = vertices[static_cast<std::size_t>(i)];
    if (v < 0 || 3 * v + 2 >= map.target_dimension())
      throw std::invalid_argument("vertex tracks: vertex " + std::to_string(v) + " is outside the mesh");
    w.middleCols<3>(3 * i) = map.weights().middleCols<3>(3 * v);
    b.segment<3>(3 * i) = map.offset().segment<3>(3 * v).transpose();
  }
  Eigen::MatrixXd phi(sources.cols(), map.response_count());
  for (Eigen::Index f = 0; f < sources.cols(); ++f) phi.row(f) = map.responses(sources.col(f)).transpose();
  return ((phi * w).rowwise() + b).cast<float>();
}

SynthesisScorer::SynthesisScorer(EvaluationPoints points) : points_(std::move(points)) {}

void SynthesisScorer::add(const Eigen::MatrixXf& recorded, const Eigen::MatrixXf& synthesised) {
  check_tracks(recorded, points_.vertices.size(), "recorded");
  check_tracks(synthesised, points_.vertices.size(), "synthesised");
  const Eigen::Index n = std::min(recorded.rows(), synthesised.rows());
  const auto a = recorded.topRows(n);
  const auto b = synthesised.topRows(n);
  recorded_.append(lip_curves(a, points_.lip_measure));
  synthesised_.append(lip_curves(b, points_.lip_measure));
  if (points_.chin) {
    append_jaw(a, points_, recorded_jaw_);
    append_jaw(b, points_, synthesised_jaw_);
  }
  auto sum_squared = [&](const std::vector<std::size_t>& which) {
    double s = 0;
    for (const std::size_t i : which)
      s += (a.middleCols<3>(3 * static_cast<Eigen::Index>(i)) - b.middleCols<3>(3 * static_cast<Eigen::Index>(i)))
               .cast<double>().squaredNorm();
    return s;
  };
  lip_sum_squared_m2_ += sum_squared(points_.lip_points);
  all_sum_squared_m2_ += sum_squared(points_.feature_points);
  frames_ += static_cast<std::size_t>(n);
  ++utterances_;
}

SynthesisScore SynthesisScorer::score() const {
  SynthesisScore s;
  s.lips = compare_lip_curves(recorded_, synthesised_);
  if (!recorded_jaw_.empty()) s.jaw = compare_curves(recorded_jaw_, synthesised_jaw_);
  s.frames = frames_;
  s.utterances = utterances_;
  auto rms_mm = [&](double sum, std::size_t points) {
    const double samples = static_cast<double>(frames_) * static_cast<double>(points);
    return samples > 0 ? 1000.0 * std::sqrt(sum / samples) : 0.0;
  };
  s.lip_rms_mm = rms_mm(lip_sum_squared_m2_, points_.lip_points.size());
  s.all_rms_mm = rms_mm(all_sum_squared_m2_, points_.feature_points.size());
  return s;
}

}  // namespace fapcast
