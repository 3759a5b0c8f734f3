#include "fapcast/select/join_sketch.hpp"

#include "fapcast/select/phone_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fapcast {

SketchGrid sketch_grid(const JoinFeatures& features) {
  // From at most about 1,024 evenly spaced rows of each table: any grid is exact (values beyond
  // reach are clamped, widening only their rows' rounding norms), the sample only tunes it.
  double largest = 0.0, squares = 0.0, values = 0.0;
  for (const JoinRows* rows : {&features.entry, &features.exit}) {
    const Eigen::Index stride = std::max<Eigen::Index>(1, rows->rows() / 1024);
    for (Eigen::Index r = 0; r < rows->rows(); r += stride) {
      largest = std::max(largest, static_cast<double>(rows->row(r).cwiseAbs().maxCoeff()));
      squares += static_cast<double>(rows->row(r).squaredNorm());
      values += static_cast<double>(rows->cols());
    }
  }
  if (values == 0) return {};
  const double reach = std::min(largest, 8.0 * std::sqrt(squares / values));
  if (!(reach > 0.0) || !std::isfinite(reach)) return {};
  // step >= reach / kSketchReach, a power of two within float's range.
  const int exponent = std::clamp(static_cast<int>(std::ceil(std::log2(reach / kSketchReach))), -100, 100);
  return {std::ldexp(1.0f, -exponent), std::ldexp(1.0, exponent)};
}

float sketch_row(const float* row, Eigen::Index dims, const SketchGrid& grid, std::int16_t* out) {
  using Four = Eigen::Array4f;
  constexpr auto reach = static_cast<float>(kSketchReach);
  const auto step = static_cast<float>(grid.step);
  Four low = Four::Zero(), high = Four::Zero();  // squared rounding errors, lanes 0-3 and 4-7
  for (Eigen::Index d = 0; d < dims; d += 4) {  // dims is a multiple of kJoinLanes
    const Four v = Eigen::Map<const Four>(row + d);
    Four y = (v * grid.scale).max(-reach).min(reach);
    y = (y == y).select(y, Four::Zero());  // NaN: 0 (its rounding norm is NaN, which bounds nothing)
    const Eigen::Array4i q = (y + (y >= 0.0f).select(Four::Constant(0.5f), Four::Constant(-0.5f))).cast<int>();
    for (int l = 0; l < 4; ++l) out[d + l] = static_cast<std::int16_t>(q[l]);
    // Exact unless clamped (Sterbenz: row[d] and q step are within a factor 2 when |q| >= 1).
    const Four moved = v - q.cast<float>() * step;
    ((d / 4) % 2 == 0 ? low : high) += moved * moved;
  }
  const Four lane = low + high;
  const float sum = (lane[0] + lane[2]) + (lane[1] + lane[3]);
  // A float sum of <= kSketchMaxDims squares is within 2^-16.9 of the exact one; the square root
  // halves that; 2^-15 more covers both and the root's own rounding.
  return std::sqrt(sum) * (1.0f + 0x1p-15f);
}

}  // namespace fapcast
