#pragma once
// A second exact lower bound on the join cost C(i, j), for the joins that the axis bound of
// join_bound.hpp cannot tell apart (spec/search.md, "Pruning the joins").
//
// A sketch of a boundary row rounds each value to the nearest multiple of a step h = 2^-n (at
// most kSketchReach steps from 0, clamped beyond), kept as int16, together with an upper bound
// of the norm of what the rounding moved. For rows e, x with sketches ê, x̂ and rounding norms
// δe, δx, the triangle inequality gives
//   |e - x| >= h |ê - x̂| - (δe + δx),   so   2 C(i, j) >= (h |ê - x̂| - δe - δx)^2 when positive.
// |ê - x̂|^2 is an exact integer summed in int16 lanes (no rounding, the same on every instruction
// set), about a third of the float cost's work. Where the axis bound loses up to 2 s t (the
// residuals' inner product), this one loses about 2 |e - x| (δe + δx): a few per cent of C.
#include <Eigen/Core>

#include <cmath>
#include <cstdint>

namespace fapcast {

struct JoinFeatures;  // phone_graph.hpp

// At most this many steps from 0, so that no sum of squared differences of <= kSketchMaxDims
// values overflows int32 (kSketchMaxDims (2 x 2047)^2 < 2^31).
inline constexpr std::int32_t kSketchReach = 2047;
inline constexpr Eigen::Index kSketchMaxDims = 128;

// The grid of a graph's sketches: step = 2^-n, scale = 1 / step (both exact).
struct SketchGrid {
  float scale = 1.0f;
  double step = 1.0;
};

// The grid for rows of this size: the smallest power-of-two step at which a row value of
// min(largest |value|, 8 x root mean square), over a sample of the rows, is within kSketchReach
// steps (larger values are clamped, which only widens their own rows' rounding norms).
SketchGrid sketch_grid(const JoinFeatures& features);

// Rounds the `dims` floats of `row` onto `grid` into `out` (dims int16); returns an upper bound of
// the norm of the rounding error (infinite or NaN rows give a norm that bounds nothing).
float sketch_row(const float* row, Eigen::Index dims, const SketchGrid& grid, std::int16_t* out);

// |a - b|^2 of two sketches of `dims` values, exactly. Dims > 0 fixes the width at compile time.
template <Eigen::Index Dims = 0>
inline std::int32_t sketch_distance2(const std::int16_t* a, const std::int16_t* b, Eigen::Index dims = Dims) {
  const Eigen::Index width = Dims > 0 ? Dims : dims;
  std::int32_t sum = 0;
  for (Eigen::Index d = 0; d < width; ++d) {
    // Both within kSketchReach of 0, so the difference fits int16 (the compiler's psubw/pmaddwd).
    const auto g = static_cast<std::int16_t>(a[d] - b[d]);
    sum += g * g;
  }
  return sum;
}

// A lower bound on the float join_cost of two rows whose sketches are `distance2` apart and
// whose rounding norms sum to `error`: (1 - 2^-16) / 2 (h sqrt(distance2) - error)^2. The factor
// covers the float cost's own rounding (below 2^-17 of it for <= kSketchMaxDims values) and the
// bound's double arithmetic.
inline double sketch_cost_floor(std::int32_t distance2, double error, double step) {
  const double reach = step * std::sqrt(static_cast<double>(distance2)) * (1.0 - 0x1p-50) - error;
  return reach > 0.0 ? (0.5 - 0x1p-17) * reach * reach : 0.0;
}

}  // namespace fapcast
