#include "fapcast/synth/junction_sketch.hpp"

#include "fapcast/synth/phone_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fapcast::synth {

SketchGrid sketch_grid(const JunctionFeatures& features) {
  const auto values = static_cast<double>(features.entry.size() + features.exit.size());
  if (values == 0) return {};
  const double largest = std::max(features.entry.cwiseAbs().maxCoeff(), features.exit.cwiseAbs().maxCoeff());
  const double rms = std::sqrt((features.entry.cast<double>().squaredNorm() + features.exit.cast<double>().squaredNorm()) / values);
  const double reach = std::min(largest, 8.0 * rms);
  if (!(reach > 0.0) || !std::isfinite(reach)) return {};
  // step >= reach / kSketchReach, a power of two within float's range.
  const int exponent = std::clamp(static_cast<int>(std::ceil(std::log2(reach / kSketchReach))), -100, 100);
  return {std::ldexp(1.0f, -exponent), std::ldexp(1.0, exponent)};
}

float sketch_row(const float* row, Eigen::Index dims, const SketchGrid& grid, std::int16_t* out) {
  constexpr auto reach = static_cast<float>(kSketchReach);
  const auto step = static_cast<float>(grid.step);
  float lane[8] = {};
  for (Eigen::Index d = 0; d < dims; ++d) {
    const float y = std::min(std::max(row[d] * grid.scale, -reach), reach);
    const float c = y == y ? y : 0.0f;  // NaN: 0 (its rounding norm is NaN, which bounds nothing)
    const auto q = static_cast<std::int32_t>(c + (c >= 0.0f ? 0.5f : -0.5f));
    out[d] = static_cast<std::int16_t>(q);
    // Exact unless clamped (Sterbenz: row[d] and q step are within a factor 2 when |q| >= 1).
    const float moved = row[d] - static_cast<float>(q) * step;
    lane[d % 8] += moved * moved;
  }
  const float sum = ((lane[0] + lane[4]) + (lane[1] + lane[5])) + ((lane[2] + lane[6]) + (lane[3] + lane[7]));
  // A float sum of <= kSketchMaxDims squares is within 2^-16.9 of the exact one; the square root
  // halves that; 2^-15 more covers both and the root's own rounding.
  return std::sqrt(sum) * (1.0f + 0x1p-15f);
}

}  // namespace fapcast::synth
