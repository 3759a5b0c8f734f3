#pragma once
// An exact lower bound on the join cost C(i, j) from three numbers per state, so that the
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
//
// Opening a voice computes only the centres and axes (O(states x 2k)); the points of a diviseme
// are computed the first time a search joins into it (O((states of a + entries of a b) x 2k)), so
// a one-sentence synthesis pays for the few divisemes it uses, not for all of them. The same
// lazy tables hold the rows' sketches, the second bound (join_sketch.hpp).
#include "fapcast/select/join_sketch.hpp"
#include "fapcast/phonetics/viseme.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace fapcast {

class PhoneGraph;

// A state's boundary row on the axis of one diviseme: `along` = u (or v), `across` = s (or t).
// `slack` is a rounding allowance, subtracted so that the float bound stays below the float cost.
struct JoinPoint {
  float along = 0.0f;
  float across = 0.0f;
  float slack = 0.0f;
};

// The entries of one diviseme a b in the order of PhoneGraph::entries(a, b): their points and
// their entry rows, each contiguous (the search reads a diviseme's entries in one sweep).
struct DivisemePoints {
  std::vector<JoinPoint> entry;
  Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> entry_rows;
  double along_mean = 0.0, across_mean = 0.0;  // the entries' mean point (u', s')
};

// The sketches (join_sketch.hpp) of a diviseme's entries, in the same order: entry_rows.cols()
// values each, and their rounding norms.
struct DivisemeSketches {
  std::vector<std::int16_t> entry;
  std::vector<float> error;
};

// A state's exit sketch: its values and rounding norm.
struct SketchRef {
  const std::int16_t* values = nullptr;
  float error = 0.0f;
};

class JoinBound {
 public:
  JoinBound() = default;  // no join features: no bound (empty())
  // O(states x 2k): the class centres and the diviseme axes. The graph must have join
  // features.
  explicit JoinBound(const PhoneGraph& graph);

  bool empty() const { return !shared_; }

  // The entry points of diviseme (from, to), computed on the first call (safe from several
  // threads) from `graph`, which must be the graph this bound was made from.
  const DivisemePoints& points(const PhoneGraph& graph, VisemeClass from, VisemeClass to) const;

  // The exit points of `states` (all of class `from`) on the axis of diviseme (from, to), into
  // `out`. Computed per call until the diviseme has computed as many as its class has states;
  // then every exit of the class is tabled once (safe from several threads) and read from there:
  // a one-sentence search pays for its predecessors only, a long-running process for each
  // point once. Either way the same values.
  void exits(const PhoneGraph& graph, VisemeClass from, VisemeClass to, std::span<const std::uint32_t> states,
             std::span<JoinPoint> out) const;

  // Whether there are sketches (join_sketch.hpp): rows of at most kSketchMaxDims values.
  bool sketched() const { return shared_ && shared_->sketched; }
  const SketchGrid& sketch_grid() const { return shared_->grid; }

  // The entry sketches of diviseme (from, to), made on its second call (safe from several
  // threads); nullptr on the first, and without sketches. A one-sentence search joins into most
  // of its divisemes once, where making sketches would cost more than they spare.
  const DivisemeSketches* entry_sketches(const PhoneGraph& graph, VisemeClass from, VisemeClass to) const;

  // The exit sketches of `states` (all of class `from`), into `out`. Like exits(): made per call
  // into `buffer` until the class has made as many as it has states, then read from a table of
  // every exit of the class made once (safe from several threads). `buffer` must stay alive and
  // untouched while `out` is read.
  void exit_sketches(const PhoneGraph& graph, VisemeClass from, std::span<const std::uint32_t> states,
                     std::span<SketchRef> out, std::vector<std::int16_t>& buffer) const;

  // A lower bound on 2 C(i, j) for exit point x and entry point e of the same diviseme; may be
  // negative (then it bounds nothing).
  static float twice_cost_floor(const JoinPoint& e, const JoinPoint& x) {
    const float da = e.along - x.along, dc = e.across - x.across;
    return da * da + dc * dc - e.slack - x.slack;
  }

 private:
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  struct Lazy;
  struct ClassSketches;
  struct Shared {
    Rows centre;                       // c_a, per class
    Rows axis;                         // q_ab, per diviseme (zero when not recorded)
    double slack_per_spread = 0.0;
    std::vector<std::uint32_t> rank;   // a state's index in PhoneGraph::with_viseme(its class)
    std::unique_ptr<Lazy[]> divisemes; // per diviseme, filled on first use
    bool sketched = false;
    SketchGrid grid;
    std::unique_ptr<ClassSketches[]> sketches;  // per class (of the exits), filled on first use
    ~Shared();
  };
  // Shared by copies of the graph (the points depend only on the features, which copies share).
  std::shared_ptr<Shared> shared_;
};

}  // namespace fapcast
