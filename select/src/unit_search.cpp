#include "fapcast/select/unit_search.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace fapcast {
namespace {

constexpr std::uint32_t kNoBack = std::numeric_limits<std::uint32_t>::max();

// The target terms of SearchOptions, what state j costs as target phone t whatever came before:
// the duration term, weight * ln^2(frames of state j / frames of target t) (a state's part depends
// only on its frame count, so ln n is tabled by count as counts appear), and the jaw term,
// weight * (recorded jaw of j - wanted jaw of t)^2.
class TargetTerm {
 public:
  TargetTerm(const PhoneGraph& graph, const SearchTargets& targets, const SearchOptions& options)
      : graph_(graph), weight_(targets.frames.empty() ? 0.0 : options.duration_weight),
        jaw_weight_(targets.jaw.empty() ? 0.0 : options.jaw_weight), state_jaw_(targets.state_jaw),
        jaw_(targets.jaw) {
    if (weight_ == 0.0) return;
    log_target_.reserve(targets.frames.size());
    for (std::size_t t = 0; t < targets.frames.size(); ++t) {
      if (targets.frames[t] < 1)
        throw std::invalid_argument("unit search: target phone " + std::to_string(t) + " lasts " +
                                    std::to_string(targets.frames[t]) + " frames (the duration term needs >= 1)");
      log_target_.push_back(std::log(static_cast<double>(targets.frames[t])));
    }
  }

  bool on() const { return weight_ != 0.0 || jaw_weight_ != 0.0; }

  // What state j costs as target phone t (0 when the terms are off).
  double operator()(StateId j, std::size_t t) {
    double cost = 0.0;
    if (weight_ != 0.0) {
      const double d = log_count(graph_.state(j).frames.count) - log_target_[t];
      cost += weight_ * d * d;
    }
    if (jaw_weight_ != 0.0) {
      const double d = static_cast<double>(state_jaw_[j]) - static_cast<double>(jaw_[t]);
      cost += jaw_weight_ * d * d;
    }
    return cost;
  }

 private:
  double log_count(std::uint32_t n) {
    n = std::max<std::uint32_t>(n, 1);  // a state always shows at least one frame
    while (log_of_.size() <= n) log_of_.push_back(std::log(static_cast<double>(std::max<std::size_t>(log_of_.size(), 1))));
    return log_of_[n];
  }

  const PhoneGraph& graph_;
  double weight_;
  double jaw_weight_;
  std::span<const float> state_jaw_;
  std::span<const float> jaw_;
  std::vector<double> log_target_;  // ln n_t per target
  std::vector<double> log_of_;      // ln n by count n
};

// One active state at one target phone: its best cost so far and where that came from.
struct Active {
  StateId state;
  double cost;
  std::uint32_t back;  // index into the previous step's actives
  bool joined;         // arrived by a join (a new unit starts here)
};

// Deterministic order: cheaper first, then lower state id. Every choice the search makes (the
// predecessor of a join, the states the cap keeps, the final state) depends only on this order,
// never on where a state sits in a vector, so skipping work cannot change a result.
bool better(const Active& a, const Active& b) {
  return a.cost < b.cost || (a.cost == b.cost && a.state < b.state);
}

// The actives of one step, at most one per state: the continuations (distinct states), then the
// joins into one ascending list of distinct targets (PhoneGraph::entries or with_viseme), merged
// with the continuations among them. No per-state table: a step touches few states of many.
class StepBuilder {
 public:
  // A state not in the step yet.
  void add(StateId j, double cost, std::uint32_t back, bool joined) { out_.push_back({j, cost, back, joined}); }

  // Starts the joins into `targets` (ascending): finds the states already in the step among them.
  void begin_joins(std::span<const StateId> targets) {
    target_slot_.assign(targets.size(), kNoBack);
    for (std::uint32_t s = 0; s < out_.size(); ++s) {
      const auto at = std::lower_bound(targets.begin(), targets.end(), out_[s].state);
      if (at != targets.end() && *at == out_[s].state) target_slot_[static_cast<std::size_t>(at - targets.begin())] = s;
    }
  }
  bool has_target(std::size_t b) const { return target_slot_[b] != kNoBack; }
  // Offers targets[b] = j as a join at `cost` (kept when cheaper than a continuation into j).
  void join(std::size_t b, StateId j, double cost, std::uint32_t back) {
    const std::uint32_t s = target_slot_[b];
    if (s == kNoBack) out_.push_back({j, cost, back, true});
    else if (cost < out_[s].cost) out_[s] = {j, cost, back, true};
  }

  bool empty() const { return out_.empty(); }
  // The step's actives (to prune in place, copy out, then clear for the next step).
  std::vector<Active>& actives() { return out_; }

 private:
  std::vector<Active> out_;
  std::vector<std::uint32_t> target_slot_;  // per target: its index in out_, kNoBack when absent
};

// The k-th smallest (from 0) of `values` (reordered; k < size, no NaN). A quickselect whose
// partitions have no data-dependent branch: the costs are in random order, and std::nth_element's
// mispredicted branches cost more than its comparisons.
double kth_smallest(std::vector<double>& values, std::size_t k, std::vector<double>& spare) {
  std::size_t lo = 0, hi = values.size();  // values[lo, hi) holds the answer
  spare.resize(values.size());
  while (hi - lo > 16) {
    const double a = values[lo], b = values[lo + (hi - lo) / 2], c = values[hi - 1];
    const double pivot = std::max(std::min(a, b), std::min(std::max(a, b), c));  // median of three
    // Smaller ones to the front of spare, larger ones to its back; what is left between equals
    // the pivot. Each value is written to both ends, and only the end it belongs to advances.
    std::size_t less = 0, more = hi - lo;
    for (std::size_t i = lo; i < hi; ++i) {
      const double x = values[i];
      spare[less] = x;
      spare[more - 1] = x;
      less += x < pivot;
      more -= x > pivot;
    }
    if (k < lo + less) {
      std::copy_n(spare.begin(), less, values.begin() + static_cast<std::ptrdiff_t>(lo));
      hi = lo + less;
    } else if (k >= lo + more) {
      std::copy(spare.begin() + static_cast<std::ptrdiff_t>(more), spare.begin() + static_cast<std::ptrdiff_t>(hi - lo),
                values.begin() + static_cast<std::ptrdiff_t>(lo + more));
      lo += more;
    } else {
      return pivot;
    }
  }
  std::sort(values.begin() + static_cast<std::ptrdiff_t>(lo), values.begin() + static_cast<std::ptrdiff_t>(hi));
  return values[k];
}

// What the cap will keep, bounded from above: the cap-th smallest of costs that each bound the
// final cost of a distinct state of the step from above (an offer's cost: a state's cost can only
// fall). A state whose cost exceeds this has the cap's worth of states strictly cheaper, so it
// cannot be kept.
class CapLimit {
 public:
  explicit CapLimit(std::optional<std::size_t> cap) : cap_(cap ? std::max<std::size_t>(*cap, 1) : 0) {}

  void add(double cost) {
    if (cap_ == 0) return;
    costs_.push_back(cost);
    unordered_ |= std::isnan(cost);
    limit_.reset();
  }

  // The cap-th smallest so far (infinity with fewer, without a cap, or when a cost is NaN).
  double limit() {
    if (cap_ == 0 || unordered_ || costs_.size() < cap_) return std::numeric_limits<double>::infinity();
    if (!limit_) limit_ = kth_smallest(costs_, cap_ - 1, spare_);
    return *limit_;
  }

  void clear() {
    costs_.clear();
    unordered_ = false;
    limit_.reset();
  }

 private:
  std::size_t cap_;
  std::vector<double> costs_, spare_;
  bool unordered_ = false;
  std::optional<double> limit_;
};

// One active of the previous step as the join loop reads it; the loop reads them in ascending
// `key`, a lower bound on what any join from it costs once the target's own part is added (see
// offer_pruned_joins).
struct Predecessor {
  double key;
  double base;           // cost + 1: a join's cost before its join term
  JoinPoint point;   // on the axis of the diviseme being joined (when bounded)
  SketchRef sketch;      // its exit sketch (when bounded and sketched)
  std::uint32_t index;   // into prev
  StateId state;
  const float* exit;     // its exit row
};

// The two classes of a join: the one left (the parent of the entry) and the one entered.
struct Diviseme {
  VisemeClass from, to;
};

// Buffers the join loop reuses from step to step.
struct JoinScratch {
  std::vector<Predecessor> pred;       // in ascending key
  std::vector<std::pair<double, std::uint32_t>> by_key;  // (key, index into prev), to sort
  std::vector<StateId> pred_state;     // the predecessors' states, in prev order
  std::vector<JoinPoint> pred_point;  // and their exit points on the diviseme's axis
  std::vector<StateId> read_state;        // the states of the predecessors read past the lead
  std::vector<SketchRef> read_sketch;     // and their exit sketches
  std::vector<std::int16_t> sketch_buffer;  // where those are made until the class is tabled
  std::vector<double> floor;           // per target
  std::vector<double> lead_cost;       // per target: its join from the predecessor of least key
  std::vector<double> duration;        // per target: its target terms (duration, jaw) at this step
};

// A join's predecessor: the cheapest (cost, state), as `better` orders them.
struct Choice {
  double cost;
  std::uint32_t back = kNoBack;
  StateId state = 0;
  // Whether (c, s) beats the choice so far (then it becomes the choice).
  bool consider(double c, std::uint32_t a, StateId s) {
    if (!(c < cost || (c == cost && (back == kNoBack || s < state)))) return false;
    cost = c, back = a, state = s;
    return true;
  }
};

// Runs `loop.template operator()<Dims>()` with Dims = `width` when it is one of the usual row
// widths (2k up to 64, rounded to kJoinLanes), so the join cost unrolls; else Dims = 0.
template <class Loop>
void join_with_width(Eigen::Index width, Loop&& loop) {
  switch (width) {
    case 8: return loop.template operator()<8>();
    case 16: return loop.template operator()<16>();
    case 24: return loop.template operator()<24>();
    case 32: return loop.template operator()<32>();
    case 40: return loop.template operator()<40>();
    case 48: return loop.template operator()<48>();
    case 56: return loop.template operator()<56>();
    case 64: return loop.template operator()<64>();
    default: return loop.template operator()<0>();
  }
}

// The least bound that exceeds `cost` by more than double rounding of the costs could explain
// (a key-based bound and a cost are different sums of the same terms; the rounding of the
// expanded squares is absorbed by the points' slacks, which scale with the spreads).
double clearly_above(double cost) { return cost + 1e-12 * (1.0 + std::abs(cost)); }

// Offers every state in `targets` as a join from its best predecessor, at 1 + beta * C(i, j),
// plus the entry's target terms at target phone t. The reference: every pair evaluated.
void offer_every_join(const PhoneGraph& graph, std::span<const Active> prev,
                      std::span<const StateId> targets, double beta, TargetTerm& target_cost, std::size_t t,
                      StepBuilder& step) {
  const auto& f = graph.join_features();
  const auto dims = f.entry.cols();
  for (std::size_t b = 0; b < targets.size(); ++b) {
    const StateId j = targets[b];
    Choice best{std::numeric_limits<double>::infinity()};
    for (std::uint32_t a = 0; a < prev.size(); ++a)
      best.consider(prev[a].cost + 1.0 + beta * join_cost(f.entry.row(j).data(), f.exit.row(prev[a].state).data(), dims),
                    a, prev[a].state);
    step.join(b, j, best.cost + target_cost(j, t), best.back);
  }
}

// The same offers, skipping what cannot matter. Every skipped pair costs strictly more than the
// join chosen, and every join not offered costs more than the cap keeps, so what survives the cap
// is the reference's, to the bit.
//
// With the bound of join_bound.hpp (when `to` names the diviseme, so that every target's
// entry point and every predecessor's exit point lie on one axis), a join n -> j costs at least
//   lb(n, j) = base_n + (beta / 2) ((u_j - v_n)^2 + (s_j - t_n)^2 - slack_j - slack_n).
// Expanding the squares around the targets' mean point (u', s') and the predecessors' mean point
// (v', t') splits it into a predecessor part and a target part:
//   lb(n, j) >= key_n + floor_j, key_n = base_n + (beta / 2) (v_n^2 + t_n^2 - slack_n) - beta (u' v_n + s' t_n),
//   floor_j = (beta / 2) (u_j^2 + s_j^2 - slack_j) - beta ((u_j - u') v' + (s_j - s') t')
//             - beta (|u_j - u'| R_v + |s_j - s'| R_t),
// with R_v, R_t the largest distances of the v_n, t_n from their means. The targets' points
// differ little, so the last line is small: reading predecessors in ascending key, a target
// stops at the first whose key_n + floor_j exceeds its best join (or what the cap keeps), usually
// after a few. Without the bound, key_n = base_n and floor_j = 0 (C >= 0). A predecessor read is
// passed over when the sketch bound (join_sketch.hpp) of its join exceeds the best so far.
//
// The target terms d_j of an entry (duration, jaw) do not depend on the predecessor: the best predecessor is
// chosen on the join's cost alone and d_j is added to what is offered (as the reference does), so
// the cap's limit L bounds the join's own cost by L - d_j (loosened by rounding: a join offered in
// excess is dropped by the cap as the reference drops it; one left out never could have survived).
//
// Order of work: (1) the predecessor of least key (the lead) joined into every target exactly,
// which gives the cap's limit before any target is searched further; (2) per target, its best
// starts at the lead's join (or the limit) and the other predecessors are read in ascending key,
// only those that some target can reach being sorted.
void offer_pruned_joins(const PhoneGraph& graph, std::span<const Active> prev,
                        std::span<const StateId> targets, std::optional<Diviseme> diviseme, double beta,
                        TargetTerm& target_cost, std::size_t t, CapLimit& cap, StepBuilder& step,
                        JoinScratch& scratch) {
  const auto& f = graph.join_features();
  const auto dims = f.entry.cols();
  const auto& bound = graph.join_bound();
  const bool bounded = diviseme && !bound.empty();
  const DivisemeSketches* entry_sketches = bounded ? bound.entry_sketches(graph, diviseme->from, diviseme->to) : nullptr;
  const bool sketched = entry_sketches != nullptr;
  // A bounded sweep reads the diviseme's entry rows and points where they lie contiguously.
  const DivisemePoints* points = bounded ? &bound.points(graph, diviseme->from, diviseme->to) : nullptr;
  const std::span<const JoinPoint> entry_point = bounded ? std::span(points->entry) : std::span<const JoinPoint>{};
  const float* entry_rows = bounded ? points->entry_rows.data() : nullptr;
  const double half_beta = 0.5 * beta;
  const double grid_step = sketched ? bound.sketch_grid().step : 0.0;
  const std::size_t preds = prev.size();

  auto& point = scratch.pred_point;
  auto& by_key = scratch.by_key;
  by_key.resize(preds);
  auto& floor = scratch.floor;
  floor.assign(targets.size(), 0.0);
  if (bounded) {
    scratch.pred_state.resize(preds);
    point.resize(preds);
    for (std::uint32_t a = 0; a < preds; ++a) scratch.pred_state[a] = prev[a].state;
    bound.exits(graph, diviseme->from, diviseme->to, scratch.pred_state, point);
    const double u_mean = points->along_mean, s_mean = points->across_mean;
    double v_mean = 0.0, t_mean = 0.0;
    for (const JoinPoint& x : point) v_mean += x.along, t_mean += x.across;
    v_mean /= static_cast<double>(preds), t_mean /= static_cast<double>(preds);
    double v_reach = 0.0, t_reach = 0.0;
    for (std::uint32_t a = 0; a < preds; ++a) {
      const double v = point[a].along, w = point[a].across;  // v_n, t_n (t names the target phone here)
      v_reach = std::max(v_reach, std::abs(v - v_mean)), t_reach = std::max(t_reach, std::abs(w - t_mean));
      by_key[a] = {prev[a].cost + 1.0 + half_beta * (v * v + w * w - point[a].slack) - beta * (u_mean * v + s_mean * w), a};
    }
    for (std::size_t b = 0; b < targets.size(); ++b) {
      const JoinPoint& e = entry_point[b];
      const double u = e.along, s = e.across, du = u - u_mean, ds = s - s_mean;
      floor[b] = half_beta * (u * u + s * s - e.slack) -
                 beta * (du * v_mean + ds * t_mean + std::abs(du) * v_reach + std::abs(ds) * t_reach);
    }
  } else {
    point.assign(preds, JoinPoint{});
    for (std::uint32_t a = 0; a < preds; ++a) by_key[a] = {prev[a].cost + 1.0, a};
  }
  const auto predecessor = [&](std::pair<double, std::uint32_t> by) {
    const auto [key, a] = by;
    const StateId i = prev[a].state;
    return Predecessor{key, prev[a].cost + 1.0, point[a], SketchRef{}, a, i, f.exit.row(i).data()};
  };

  // 1. Every target's join from the predecessor of least key (the one that most often wins):
  //    the cap's limit follows from these costs before any target is searched further.
  const auto entry_row = [&](std::size_t b) {
    return bounded ? entry_rows + static_cast<std::ptrdiff_t>(b) * dims : f.entry.row(targets[b]).data();
  };
  const auto by_key_less = [](const auto& x, const auto& y) { return x.first < y.first; };
  std::iter_swap(by_key.begin(), std::min_element(by_key.begin(), by_key.end(), by_key_less));
  const Predecessor lead = predecessor(by_key.front());
  auto& lead_cost = scratch.lead_cost;
  lead_cost.resize(targets.size());
  join_with_width(dims, [&]<Eigen::Index Dims>() {
    for (std::size_t b = 0; b < targets.size(); ++b)
      lead_cost[b] = lead.base + beta * join_cost<Dims>(entry_row(b), lead.exit, dims);
  });
  auto& dur = scratch.duration;
  dur.assign(targets.size(), 0.0);
  if (target_cost.on())
    for (std::size_t b = 0; b < targets.size(); ++b) dur[b] = target_cost(targets[b], t);
  for (std::size_t b = 0; b < targets.size(); ++b)
    if (!step.has_target(b)) cap.add(lead_cost[b] + dur[b]);  // a continuation's cost is in already
  const double limit = cap.limit();
  // What target b's join itself may cost to be kept (its target terms come on top).
  const auto join_limit = [&](std::size_t b) { return std::isinf(limit) ? limit : clearly_above(limit - dur[b]); };
  // The others in ascending key (ties in any order: a choice never depends on reading order, see
  // Choice), as far as any target could read: its best starts at most at its lead cost.
  double reach = -std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < targets.size(); ++b)
    reach = std::max(reach, clearly_above(std::min(join_limit(b), lead_cost[b])) - floor[b]);
  const auto readable = std::partition(by_key.begin() + 1, by_key.end(), [reach](const auto& x) { return x.first <= reach; });
  std::sort(by_key.begin() + 1, readable, by_key_less);
  auto& p = scratch.pred;
  p.clear();
  std::transform(by_key.begin() + 1, readable, std::back_inserter(p), predecessor);
  if (sketched) {  // only those read past the lead need a sketch
    scratch.read_state.clear();
    for (const Predecessor& x : p) scratch.read_state.push_back(x.state);
    scratch.read_sketch.resize(p.size());
    bound.exit_sketches(graph, diviseme->from, scratch.read_state, scratch.read_sketch, scratch.sketch_buffer);
    for (std::size_t r = 0; r < p.size(); ++r) p[r].sketch = scratch.read_sketch[r];
  }

  // 2. The other predecessors, in ascending key, as long as one might beat the best so far.
  join_with_width(dims, [&]<Eigen::Index Dims>() {
    for (std::size_t b = 0; b < targets.size(); ++b) {
      const float* entry = entry_row(b);
      const JoinPoint e = bounded ? entry_point[b] : JoinPoint{};
      const std::int16_t* sketch = sketched ? entry_sketches->entry.data() + static_cast<std::ptrdiff_t>(b) * dims : nullptr;
      const double sketch_error = sketched ? entry_sketches->error[b] : 0.0;
      Choice best{join_limit(b)};
      best.consider(lead_cost[b], lead.index, lead.state);
      double stop = clearly_above(best.cost) - floor[b];  // read no predecessor whose key exceeds this
      for (auto x = p.begin(); x != p.end() && x->key <= stop; ++x) {
        if (sketched) {
          const double c_floor = sketch_cost_floor(sketch_distance2<Dims>(sketch, x->sketch.values, dims),
                                                   sketch_error + x->sketch.error, grid_step);
          if (x->base + beta * c_floor > best.cost) continue;
        } else if (bounded && x->base + half_beta * JoinBound::twice_cost_floor(e, x->point) > best.cost) {
          continue;
        }
        if (best.consider(x->base + beta * join_cost<Dims>(entry, x->exit, dims), x->index, x->state))
          stop = clearly_above(best.cost) - floor[b];
      }
      if (best.back != kNoBack) step.join(b, targets[b], best.cost + dur[b], best.back);  // else dearer than the cap keeps
    }
  });
}

// Offers the joins into `targets` (the entries of `diviseme` when set, else any states).
// With beta = 0 (or no features) C drops out and the cheapest active wins every join.
void offer_joins(const PhoneGraph& graph, std::span<const Active> prev, std::span<const StateId> targets,
                 std::optional<Diviseme> diviseme, const SearchOptions& options, TargetTerm& target_cost, std::size_t t,
                 CapLimit& cap, StepBuilder& step, JoinScratch& scratch) {
  if (targets.empty() || prev.empty()) return;
  step.begin_joins(targets);
  if (options.beta == 0.0 || !graph.has_join_features()) {
    const auto best = std::min_element(prev.begin(), prev.end(), better);
    const auto back = static_cast<std::uint32_t>(best - prev.begin());
    for (std::size_t b = 0; b < targets.size(); ++b)
      step.join(b, targets[b], best->cost + 1.0 + target_cost(targets[b], t), back);
    return;
  }
  if (!options.prune_joins) return offer_every_join(graph, prev, targets, options.beta, target_cost, t, step);
  offer_pruned_joins(graph, prev, targets, diviseme, options.beta, target_cost, t, cap, step, scratch);
}

// Keeps the cap's worth of cheapest actives. `limit` is at least the cap-th smallest cost (see
// CapLimit): whatever costs more is dropped before the selection.
void prune(std::vector<Active>& actives, std::optional<std::size_t> cap, double limit) {
  if (!cap || actives.size() <= *cap) return;
  const auto keep = std::max<std::size_t>(*cap, 1);
  std::erase_if(actives, [limit](const Active& a) { return a.cost > limit; });
  if (actives.size() <= keep) return;
  std::nth_element(actives.begin(), actives.begin() + static_cast<std::ptrdiff_t>(keep) - 1, actives.end(), better);
  actives.resize(keep);
}

// The first step's cap. Every state of the first class starts at the same cost (the duration term
// aside), so the cap alone would choose among equal starts by state id: on the default voice the
// rests of the first 32 takes, whatever the sentence begins with. Kept beside the cap's worth:
// every state whose recording goes on in the second target's class, the starts of the units longer
// than one phone (the rests of the takes that begin as the sentence does). All of them would cost
// the first join's sweep more than they could win it: they all rest alike.
void prune_first_step(const PhoneGraph& graph, std::vector<Active>& actives, std::optional<std::size_t> cap,
                      std::optional<VisemeClass> second) {
  if (!cap || actives.size() <= *cap) return;
  const auto others = std::stable_partition(actives.begin(), actives.end(), [&](const Active& a) {
    return second && graph.child_viseme(a.state) == *second;
  });
  std::vector<Active> rest(others, actives.end());
  actives.erase(others, actives.end());
  prune(rest, cap, std::numeric_limits<double>::infinity());
  actives.insert(actives.end(), rest.begin(), rest.end());
  std::sort(actives.begin(), actives.end(), [](const Active& a, const Active& b) { return a.state < b.state; });
}

}  // namespace

SearchResult unit_search(const PhoneGraph& graph, std::span<const VisemeClass> targets,
                         const SearchOptions& options) {
  return unit_search(graph, targets, SearchTargets{}, options);
}

SearchResult unit_search(const PhoneGraph& graph, std::span<const VisemeClass> targets,
                         std::span<const std::int64_t> target_frames, const SearchOptions& options) {
  return unit_search(graph, targets, SearchTargets{target_frames, {}, {}}, options);
}

SearchResult unit_search(const PhoneGraph& graph, std::span<const VisemeClass> targets,
                         const SearchTargets& shape, const SearchOptions& options) {
  const auto target_frames = shape.frames;
  SearchResult result;
  if (!target_frames.empty() && target_frames.size() != targets.size())
    throw std::invalid_argument("unit search: " + std::to_string(target_frames.size()) + " target lengths for " +
                                std::to_string(targets.size()) + " target phones");
  if (targets.empty()) return result;
  if (options.beta < 0.0) throw std::invalid_argument("unit search: beta must be >= 0");
  if (!(options.duration_weight >= 0.0) || std::isinf(options.duration_weight))
    throw std::invalid_argument("unit search: the duration weight must be finite and >= 0");
  if (!(options.context_weight >= 0.0) || std::isinf(options.context_weight))
    throw std::invalid_argument("unit search: the context weight must be finite and >= 0");
  if (!(options.jaw_weight >= 0.0) || std::isinf(options.jaw_weight))
    throw std::invalid_argument("unit search: the jaw weight must be finite and >= 0");
  if (!shape.jaw.empty() && (shape.jaw.size() != targets.size() || shape.state_jaw.size() != graph.size()))
    throw std::invalid_argument("unit search: the jaw term needs one value per target phone and one per state");
  TargetTerm target_cost(graph, shape, options);
  for (std::size_t t = 0; t < targets.size(); ++t)
    if (graph.with_viseme(targets[t]).empty())
      throw std::invalid_argument("unit search: the voice has no phone of viseme class " +
                                  std::string(viseme_class_name(targets[t])) + " (target phone " +
                                  std::to_string(t) + ")");

  // The actives of every step, one after the other: step t is trail[begin[t], begin[t + 1]).
  std::vector<Active> trail;
  std::vector<std::size_t> begin{0};
  if (options.max_active) trail.reserve(targets.size() * std::max<std::size_t>(*options.max_active, 1));
  StepBuilder builder;
  CapLimit cap(options.max_active);
  const auto close_step = [&](bool first) {
    auto& actives = builder.actives();
    if (first) {
      prune_first_step(graph, actives, options.max_active, targets.size() > 1 ? std::optional(targets[1]) : std::nullopt);
    } else {
      // The reference path does without the cap's limit (prune's selection alone keeps the same).
      prune(actives, options.max_active, options.prune_joins ? cap.limit() : std::numeric_limits<double>::infinity());
    }
    trail.insert(trail.end(), actives.begin(), actives.end());
    begin.push_back(trail.size());
    result.stats.active_per_step.push_back(actives.size());
    actives.clear();
  };
  const auto step = [&](std::size_t t) { return std::span(trail).subspan(begin[t], begin[t + 1] - begin[t]); };
  result.stats.active_per_step.reserve(targets.size());
  for (StateId j : graph.with_viseme(targets[0])) builder.add(j, 1.0 + target_cost(j, 0), kNoBack, true);
  close_step(true);

  JoinScratch scratch;
  std::vector<Active> leaving;  // the previous step's actives with their right-context term
  for (std::size_t t = 1; t < targets.size(); ++t) {
    const auto kept = step(t - 1);
    cap.clear();
    // Within a recording: the next phone, free. A unit left where its recording goes on in another
    // class pays the context term, a constant per predecessor: it joins the predecessor's cost, so
    // every join path (and its pruning) sees it alike.
    const bool context = options.context_weight > 0.0;
    if (context) leaving.assign(kept.begin(), kept.end());
    for (std::uint32_t a = 0; a < kept.size(); ++a) {
      const StateId i = kept[a].state;
      if (graph.child_viseme(i) == targets[t]) {
        const double cost = kept[a].cost + target_cost(i + 1, t);
        builder.add(i + 1, cost, a, false);
        cap.add(cost);
      } else if (context) {
        leaving[a].cost += options.context_weight;
      }
    }
    // Across recordings: states whose parent looks like the phone we leave.
    const std::span<const Active> prev = context ? std::span<const Active>(leaving) : kept;
    offer_joins(graph, prev, graph.entries(targets[t - 1], targets[t]), Diviseme{targets[t - 1], targets[t]}, options,
                target_cost, t, cap, builder, scratch);
    if (builder.empty()) {  // the voice never recorded this diviseme: join anywhere that matches
      ++result.stats.hard_joins;
      offer_joins(graph, prev, graph.with_viseme(targets[t]), std::nullopt, options, target_cost, t, cap, builder,
                  scratch);
    }
    close_step(false);
  }

  // Back-trace from the cheapest final state.
  const auto last = step(targets.size() - 1);
  std::uint32_t a = static_cast<std::uint32_t>(std::min_element(last.begin(), last.end(), better) - last.begin());
  result.cost = last[a].cost;
  result.states.resize(targets.size());
  std::vector<bool> joined(targets.size());
  for (std::size_t t = targets.size(); t-- > 0;) {
    const Active& at = step(t)[a];
    result.states[t] = at.state;
    joined[t] = at.joined;
    a = at.back;
  }
  for (std::size_t t = 0; t < targets.size(); ++t) {
    if (joined[t]) result.units.push_back({result.states[t], t, 0});
    ++result.units.back().length;
  }
  return result;
}

}  // namespace fapcast
