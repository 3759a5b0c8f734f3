#include "fapcast/codec/feature_point_basis.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fapcast {

std::optional<std::size_t> FeaturePointBasis::index_of(FeaturePoint fp) const {
  const auto it = std::find(points.begin(), points.end(), fp);
  if (it == points.end()) return std::nullopt;
  return static_cast<std::size_t>(it - points.begin());
}

FeaturePointBasis restrict_basis(const Eigen::Ref<const RowMajorMatrixXf>& mean,
                                 const Eigen::Ref<const RowMajorMatrixXf>& components,
                                 std::span<const FeaturePointVertex> points,
                                 FeaturePointPositions neutral) {
  if (mean.rows() != 1 || mean.cols() != components.cols() || mean.cols() % 3 != 0)
    throw std::invalid_argument("face basis: mean is " + std::to_string(mean.rows()) + " x " +
                                std::to_string(mean.cols()) + ", components " +
                                std::to_string(components.rows()) + " x " +
                                std::to_string(components.cols()) + " (want 1 x 3N and k x 3N)");
  const std::int64_t vertices = mean.cols() / 3;
  FeaturePointBasis b;
  const auto p = static_cast<Eigen::Index>(points.size());
  b.mean.resize(3 * p);
  b.components.resize(components.rows(), 3 * p);
  for (Eigen::Index i = 0; i < p; ++i) {
    const FeaturePointVertex& fv = points[static_cast<std::size_t>(i)];
    const std::string where = "face basis: feature point " + fv.fp.label();
    if (fv.vertex < 0 || fv.vertex >= vertices)
      throw std::invalid_argument(where + ": vertex " + std::to_string(fv.vertex) + " outside 0.." +
                                  std::to_string(vertices - 1));
    if (b.index_of(fv.fp)) throw std::invalid_argument(where + " given twice");
    if (!neutral.contains(fv.fp)) throw std::invalid_argument(where + " has no neutral position");
    b.points.push_back(fv.fp);
    for (Eigen::Index a = 0; a < 3; ++a) {
      const Eigen::Index col = 3 * static_cast<Eigen::Index>(fv.vertex) + a;
      b.mean(3 * i + a) = mean(0, col);
      b.components.col(3 * i + a) = components.col(col).cast<double>();
    }
  }
  b.neutral = std::move(neutral);
  return b;
}

}  // namespace fapcast
