#pragma once
// A PCA face basis restricted to the MPEG-4 feature points: the codec's second kind of input
// (PCA frames plus a face basis, spec/synthesis.md), whatever built it. A mesh frame is
// mean + c * components for a row c of k PCA coefficients; only the feature points' columns are
// kept, so turning a frame into FAPs costs O(k x points), not O(k x mesh).
#include "fapcast/codec/fapu_values.hpp"
#include "fapcast/codec/feature_point.hpp"

#include "fapcast/core/eigen_types.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace fapcast {


// Which mesh vertex carries a feature point.
struct FeaturePointVertex {
  FeaturePoint fp;
  std::int64_t vertex = 0;  // 0-based
};

struct FeaturePointBasis {
  std::vector<FeaturePoint> points;  // P distinct points, in the order given
  Eigen::RowVectorXd mean;           // 1 x 3P: x y z of points[i] at columns 3i, 3i+1, 3i+2
  Eigen::MatrixXd components;        // k x 3P
  FeaturePointPositions neutral;     // the face's NEUTRAL feature points (rest pose, FAPU)

  Eigen::Index component_count() const { return components.rows(); }
  // Index of `fp` in `points`, if present.
  std::optional<std::size_t> index_of(FeaturePoint fp) const;
};

// Keeps the feature points' columns of a mesh basis (mean 1 x 3N, components k x 3N, vertex v
// at columns 3v..3v+2; lengths in any unit shared with `neutral`). Throws std::invalid_argument
// naming the point for a vertex out of range, a duplicate point or a point with no neutral
// position, and for a mean that is not one row as wide as the components.
FeaturePointBasis restrict_basis(const Eigen::Ref<const RowMajorMatrixXf>& mean,
                                 const Eigen::Ref<const RowMajorMatrixXf>& components,
                                 std::span<const FeaturePointVertex> points,
                                 FeaturePointPositions neutral);

}  // namespace fapcast
