#pragma once
// An exact lower bound on the junction cost C(i, j) from three numbers per state, so that the
// unit search evaluates the full 2k-dimensional cost only for joins that might win
// (spec/search.md, "Pruning the joins").
//
// A join i -> j is admissible only when class(i) = class(parent(j)) = a. With b = class(j), both
// boundary rows are taken relative to c_a, the mean exit row of class a, and split along the unit
// axis q_ab from c_a towards the mean entry row of diviseme a b:
//   e_j - c_a = u_j q_ab + r_j,   x_i - c_a = v_i q_ab + r_i,   r_j, r_i orthogonal to q_ab.
// Then 2 C(i, j) = |e_j - x_i|^2 = (u_j - v_i)^2 + |r_j - r_i|^2 >= (u_j - v_i)^2 + (s_j - t_i)^2
// with s_j = |r_j|, t_i = |r_i| (reverse triangle inequality). The bound is tight where the
// classes differ along q_ab (the usual case: an /m/ exit against an /aa/ entry) and never
// exceeds the cost.
#include "fapcast/synth/viseme.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace fapcast::synth {

class PhoneGraph;

// A state's boundary row on the axis of one diviseme: `along` = u (or v), `across` = s (or t).
// `slack` is a rounding allowance, subtracted so that the float bound stays below the float cost.
struct JunctionPoint {
  float along = 0.0f;
  float across = 0.0f;
  float slack = 0.0f;
};

class JunctionBound {
 public:
  JunctionBound() = default;  // no junction features: no bound (empty())
  // O(states x 2k). The graph must have junction features.
  // O(states x classes x 2k) once: every state's exit point on the axis of each of its divisemes
  // is computed here (in double), so that the search only reads them.
  explicit JunctionBound(const PhoneGraph& graph);

  bool empty() const { return entry_.empty(); }

  // State j as the entry of its own diviseme (class of its parent, class of j); j must have a
  // parent. Precomputed.
  const JunctionPoint& entry(std::uint32_t j) const { return entry_[j]; }

  // The entries of diviseme (from, to) in the order of PhoneGraph::entries(from, to): their points
  // and their entry rows, each contiguous (the search reads a diviseme's entries in one sweep).
  std::span<const JunctionPoint> entry_points(VisemeClass from, VisemeClass to) const {
    const auto d = diviseme(from, to);
    return std::span(entry_by_diviseme_).subspan(offset_[d], offset_[d + 1] - offset_[d]);
  }
  const float* entry_rows(VisemeClass from, VisemeClass to) const {
    return entry_rows_.data() + static_cast<std::ptrdiff_t>(offset_[diviseme(from, to)]) * entry_rows_.cols();
  }

  // State i leaving a unit towards class `to`, on the axis of diviseme (class(i), to).
  JunctionPoint exit(std::uint32_t i, VisemeClass to) const {
    const auto& p = exit_[static_cast<std::size_t>(i) * kVisemeClassCount + static_cast<std::size_t>(to)];
    return {p.along, p.across, exit_slack_[i]};
  }

  // A lower bound on 2 C(i, j) for exit point x and entry point e of the same diviseme; may be
  // negative (then it bounds nothing).
  static float twice_cost_floor(const JunctionPoint& e, const JunctionPoint& x) {
    const float da = e.along - x.along, dc = e.across - x.across;
    return da * da + dc * dc - e.slack - x.slack;
  }

 private:
  struct OnAxis {
    float along, across;
  };
  static std::size_t diviseme(VisemeClass from, VisemeClass to) {
    return static_cast<std::size_t>(from) * kVisemeClassCount + static_cast<std::size_t>(to);
  }
  std::vector<JunctionPoint> entry_;  // per state (zero for states without a parent)
  // The same points and the entry rows again, grouped by diviseme: [offset_[d], offset_[d + 1]).
  std::vector<std::size_t> offset_;
  std::vector<JunctionPoint> entry_by_diviseme_;
  Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> entry_rows_;
  std::vector<OnAxis> exit_;          // per state and class `to`
  std::vector<float> exit_slack_;     // per state
};

}  // namespace fapcast::synth
