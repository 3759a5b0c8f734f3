#include "fapcast/eval/lip_measures.hpp"

#include "fapcast/math/sample_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fapcast {

LipMeasures measure_lips(const LipPoints& p) {
  return {(p.upper_mid - p.lower_mid).norm(), (p.left_corner - p.right_corner).norm(),
          (p.upper_mid - p.reference).norm()};
}

void LipCurves::push_back(const LipMeasures& m) {
  height.push_back(m.height);
  width.push_back(m.width);
  protrusion.push_back(m.protrusion);
}

void LipCurves::append(const LipCurves& other) {
  height.insert(height.end(), other.height.begin(), other.height.end());
  width.insert(width.end(), other.width.begin(), other.width.end());
  protrusion.insert(protrusion.end(), other.protrusion.begin(), other.protrusion.end());
}

namespace {

LipPoints points_from(const std::array<Eigen::Vector3d, 6>& p) {
  return {p[0], p[1], p[2], p[3], 0.5 * (p[4] + p[5])};
}

}  // namespace

LipCurves lip_curves(const MarkerFrames<Centimetres>& take) {
  std::array<Eigen::Index, 6> rows{};
  for (std::size_t i = 0; i < kLipMarkerLabels.size(); ++i) {
    const auto it = std::find(take.labels.begin(), take.labels.end(), kLipMarkerLabels[i]);
    if (it == take.labels.end()) {
      throw std::invalid_argument("lip measures need marker " + std::string(kLipMarkerLabels[i]) +
                                  ", which the take does not have");
    }
    rows[i] = it - take.labels.begin();
  }
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  LipCurves curves;
  for (Eigen::Index k = 0; k < take.frame_count(); ++k) {
    std::array<Eigen::Vector3d, 6> p;
    bool complete = true;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      complete = complete && take.present(rows[i], k);
      p[i] = take.at(rows[i], k);
    }
    curves.push_back(complete ? measure_lips(points_from(p)) : LipMeasures{kNan, kNan, kNan});
  }
  return curves;
}

LipCurves lip_curves(const Eigen::Ref<const Eigen::MatrixXf>& frames,
                     std::span<const std::int32_t, 6> vertices) {
  for (const std::int32_t v : vertices) {
    if (v < 0 || 3 * static_cast<Eigen::Index>(v) + 2 >= frames.cols()) {
      throw std::invalid_argument("lip measure vertex " + std::to_string(v) +
                                  " is outside the mesh frames");
    }
  }
  LipCurves curves;
  for (Eigen::Index k = 0; k < frames.rows(); ++k) {
    std::array<Eigen::Vector3d, 6> p;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      p[i] = frames.block<1, 3>(k, 3 * Eigen::Index{vertices[i]}).transpose().cast<double>();
    }
    curves.push_back(measure_lips(points_from(p)));
  }
  return curves;
}

CurveAgreement compare_curves(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size()) {
    throw std::invalid_argument("lip curves differ in length: " + std::to_string(a.size()) +
                                " and " + std::to_string(b.size()) + " frames");
  }
  double max_a = 0;
  double max_b = 0;
  CurveAgreement out;
  for (std::size_t t = 0; t < a.size(); ++t) {
    if (std::isnan(a[t]) || std::isnan(b[t])) continue;
    max_a = std::max(max_a, a[t]);
    max_b = std::max(max_b, b[t]);
    ++out.frames;
  }
  if (out.frames == 0 || max_a <= 0 || max_b <= 0) return out;
  double error = 0, difference = 0;
  for (std::size_t t = 0; t < a.size(); ++t)
    if (!std::isnan(a[t]) && !std::isnan(b[t])) {
      error += std::abs(a[t] / max_a - b[t] / max_b);
      difference += std::abs(a[t] - b[t]);
    }
  out.mean_error_percent = 100.0 * error / static_cast<double>(out.frames);
  out.mean_abs_difference = difference / static_cast<double>(out.frames);
  out.correlation = pearson_correlation(a, b);  // scale-free: the normalisation does not change it
  return out;
}

LipAgreement compare_lip_curves(const LipCurves& reference, const LipCurves& candidate) {
  return {compare_curves(reference.height, candidate.height),
          compare_curves(reference.width, candidate.width),
          compare_curves(reference.protrusion, candidate.protrusion)};
}

}  // namespace fapcast
