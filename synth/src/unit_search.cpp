#include "fapcast/synth/unit_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace fapcast::synth {
namespace {

constexpr std::uint32_t kNoBack = std::numeric_limits<std::uint32_t>::max();

// The duration term of SearchOptions: weight * ln^2(frames of state j / frames of target t).
// A state's part depends only on its frame count, so ln n is tabled by count as counts appear.
class DurationTerm {
 public:
  DurationTerm(const PhoneGraph& graph, std::span<const std::int64_t> target_frames, double weight)
      : graph_(graph), weight_(target_frames.empty() ? 0.0 : weight) {
    if (weight_ == 0.0) return;
    log_target_.reserve(target_frames.size());
    for (std::size_t t = 0; t < target_frames.size(); ++t) {
      if (target_frames[t] < 1)
        throw std::invalid_argument("unit search: target phone " + std::to_string(t) + " lasts " +
                                    std::to_string(target_frames[t]) + " frames (the duration term needs >= 1)");
      log_target_.push_back(std::log(static_cast<double>(target_frames[t])));
    }
  }

  // What state j costs as target phone t (0 when the term is off).
  double operator()(StateId j, std::size_t t) {
    if (weight_ == 0.0) return 0.0;
    const double d = log_count(graph_.state(j).frames.count) - log_target_[t];
    return weight_ * d * d;
  }

 private:
  double log_count(std::uint32_t n) {
    n = std::max<std::uint32_t>(n, 1);  // a state always shows at least one frame
    while (log_of_.size() <= n) log_of_.push_back(std::log(static_cast<double>(std::max<std::size_t>(log_of_.size(), 1))));
    return log_of_[n];
  }

  const PhoneGraph& graph_;
  double weight_;
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

// The actives of one step, at most one entry per state, with O(1) lookup by state.
class StepBuilder {
 public:
  explicit StepBuilder(std::size_t states) : slot_(states, kNoBack) {}

  bool has(StateId j) const { return slot_[j] != kNoBack; }

  void offer(StateId j, double cost, std::uint32_t back, bool joined) {
    std::uint32_t& s = slot_[j];
    if (s == kNoBack) {
      s = static_cast<std::uint32_t>(out_.size());
      out_.push_back({j, cost, back, joined});
    } else if (cost < out_[s].cost) {
      out_[s] = {j, cost, back, joined};
    }
  }

  std::vector<Active> take() {
    for (const auto& a : out_) slot_[a.state] = kNoBack;
    std::vector<Active> next;
    next.reserve(out_.size());  // the next step is usually about as large
    return std::exchange(out_, std::move(next));
  }

 private:
  std::vector<std::uint32_t> slot_;  // state -> index in out_, kNoBack when absent
  std::vector<Active> out_;
};

// What the cap will keep, bounded from above while a step is built: the cap-th smallest of the
// costs offered to distinct states so far (each an upper bound of that state's final cost, which
// can only fall). A state offered more than this cannot be among the cap cheapest.
class CapLimit {
 public:
  explicit CapLimit(std::optional<std::size_t> cap) : cap_(cap ? std::max<std::size_t>(*cap, 1) : 0) {}

  void add(double cost) {
    if (cap_ == 0) return;
    if (heap_.size() < cap_) {
      heap_.push_back(cost);
      std::push_heap(heap_.begin(), heap_.end());
    } else if (cost < heap_.front()) {
      std::pop_heap(heap_.begin(), heap_.end());
      heap_.back() = cost;
      std::push_heap(heap_.begin(), heap_.end());
    }
  }

  double limit() const {
    return cap_ > 0 && heap_.size() == cap_ ? heap_.front() : std::numeric_limits<double>::infinity();
  }

  void clear() { heap_.clear(); }

 private:
  std::size_t cap_;
  std::vector<double> heap_;  // max-heap of the cap smallest costs
};

// One active of the previous step as the join loop reads it; the loop reads them in ascending
// `key`, a lower bound on what any join from it costs once the target's own part is added (see
// offer_pruned_joins).
struct Predecessor {
  double key;
  double base;           // cost + 1: a join's cost before its junction term
  JunctionPoint point;   // on the axis of the diviseme being joined (when bounded)
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
  std::vector<Predecessor> pred;
  std::vector<StateId> pred_state;     // the predecessors' states, in prev order
  std::vector<JunctionPoint> pred_point;  // and their exit points on the diviseme's axis
  std::vector<double> floor;           // per target
  std::vector<double> duration;        // per target: its duration term at this step
  std::vector<std::uint32_t> order;    // targets, the cap's worth with the lowest floor first
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
// widths (2k up to 64, rounded to kJunctionLanes), so the junction cost unrolls; else Dims = 0.
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
// plus the entry's duration term at target phone t. The reference: every pair evaluated.
void offer_every_join(const PhoneGraph& graph, const std::vector<Active>& prev,
                      std::span<const StateId> targets, double beta, DurationTerm& duration, std::size_t t,
                      StepBuilder& step) {
  const auto& f = graph.junction();
  const auto dims = f.entry.cols();
  for (StateId j : targets) {
    Choice best{std::numeric_limits<double>::infinity()};
    for (std::uint32_t a = 0; a < prev.size(); ++a)
      best.consider(prev[a].cost + 1.0 + beta * junction_cost(f.entry.row(j).data(), f.exit.row(prev[a].state).data(), dims),
                    a, prev[a].state);
    step.offer(j, best.cost + duration(j, t), best.back, true);
  }
}

// The same offers, skipping what cannot matter. Every skipped pair costs strictly more than the
// join chosen, and every join not offered costs more than the cap keeps, so what survives the cap
// is the reference's, to the bit.
//
// With the bound of junction_bound.hpp (when `to` names the diviseme, so that every target's
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
// after a few. Without the bound, key_n = base_n and floor_j = 0 (C >= 0).
//
// The duration term d_j of an entry does not depend on the predecessor: the best predecessor is
// chosen on the join's cost alone and d_j is added to what is offered (as the reference does), so
// the cap's limit L bounds the join's own cost by L - d_j (loosened by rounding: a join offered in
// excess is pruned by the cap like in the reference, one left out never could have survived).
void offer_pruned_joins(const PhoneGraph& graph, const std::vector<Active>& prev,
                        std::span<const StateId> targets, std::optional<Diviseme> diviseme, double beta,
                        DurationTerm& duration, std::size_t t, std::optional<std::size_t> max_active,
                        CapLimit& cap, StepBuilder& step, JoinScratch& scratch) {
  const auto& f = graph.junction();
  const auto dims = f.entry.cols();
  const auto& bound = graph.junction_bound();
  const bool bounded = diviseme && !bound.empty();
  // A bounded sweep reads the diviseme's entry rows and points where they lie contiguously.
  const DivisemePoints* points = bounded ? &bound.points(graph, diviseme->from, diviseme->to) : nullptr;
  const std::span<const JunctionPoint> entry_point = bounded ? std::span(points->entry) : std::span<const JunctionPoint>{};
  const float* entry_rows = bounded ? points->entry_rows.data() : nullptr;
  const double half_beta = 0.5 * beta;
  const std::size_t preds = prev.size();

  auto& p = scratch.pred;
  p.resize(preds);
  scratch.pred_point.assign(preds, JunctionPoint{});
  if (bounded) {
    scratch.pred_state.resize(preds);
    for (std::uint32_t a = 0; a < preds; ++a) scratch.pred_state[a] = prev[a].state;
    bound.exits(graph, diviseme->from, diviseme->to, scratch.pred_state, scratch.pred_point);
  }
  for (std::uint32_t a = 0; a < preds; ++a) {
    const StateId i = prev[a].state;
    const double base = prev[a].cost + 1.0;
    p[a] = {base, base, scratch.pred_point[a], a, i, f.exit.row(i).data()};
  }
  auto& floor = scratch.floor;
  floor.assign(targets.size(), 0.0);
  if (bounded) {
    double u_mean = 0.0, s_mean = 0.0, v_mean = 0.0, t_mean = 0.0;
    for (const JunctionPoint& e : entry_point) u_mean += e.along, s_mean += e.across;
    u_mean /= static_cast<double>(targets.size()), s_mean /= static_cast<double>(targets.size());
    for (const Predecessor& x : p) v_mean += x.point.along, t_mean += x.point.across;
    v_mean /= static_cast<double>(preds), t_mean /= static_cast<double>(preds);
    double v_reach = 0.0, t_reach = 0.0;
    for (Predecessor& x : p) {
      const double v = x.point.along, t = x.point.across;
      v_reach = std::max(v_reach, std::abs(v - v_mean)), t_reach = std::max(t_reach, std::abs(t - t_mean));
      x.key = x.base + half_beta * (v * v + t * t - x.point.slack) - beta * (u_mean * v + s_mean * t);
    }
    for (std::size_t b = 0; b < targets.size(); ++b) {
      const JunctionPoint& e = entry_point[b];
      const double u = e.along, s = e.across, du = u - u_mean, ds = s - s_mean;
      floor[b] = half_beta * (u * u + s * s - e.slack) - beta * (du * v_mean + ds * t_mean) -
                 beta * (std::abs(du) * v_reach + std::abs(ds) * t_reach);
    }
  }
  auto& dur = scratch.duration;
  dur.resize(targets.size());
  for (std::size_t b = 0; b < targets.size(); ++b) dur[b] = duration(targets[b], t);
  // With a cap, the targets most likely to be kept (lowest floor) go first, so that the cap's
  // limit is tight when the others are read (order changes work, never a result).
  auto& order = scratch.order;
  order.resize(targets.size());
  std::iota(order.begin(), order.end(), 0u);
  if (bounded && max_active && *max_active < targets.size())
    std::nth_element(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(*max_active), order.end(),
                     [&](std::uint32_t x, std::uint32_t y) { return floor[x] + dur[x] < floor[y] + dur[y]; });
  // Ascending key; ties in any order (a choice never depends on reading order, see Choice).
  std::sort(p.begin(), p.end(), [](const Predecessor& x, const Predecessor& y) { return x.key < y.key; });

  join_with_width(f.entry.cols(), [&]<Eigen::Index Dims>() {
    for (const std::uint32_t b : order) {
      const StateId j = targets[b];
      const float* entry = bounded ? entry_rows + static_cast<std::ptrdiff_t>(b) * dims : f.entry.row(j).data();
      const JunctionPoint e = bounded ? entry_point[b] : JunctionPoint{};
      const double limit = cap.limit();
      Choice best{std::isinf(limit) ? limit : clearly_above(limit - dur[b])};
      double stop = clearly_above(best.cost) - floor[b];  // read no predecessor whose key exceeds this
      for (const Predecessor& x : p) {
        if (x.key > stop) break;
        if (bounded && x.base + half_beta * JunctionBound::twice_cost_floor(e, x.point) > best.cost) continue;
        if (best.consider(x.base + beta * junction_cost<Dims>(entry, x.exit, dims), x.index, x.state))
          stop = clearly_above(best.cost) - floor[b];
      }
      if (best.back == kNoBack) continue;  // dearer than the cap keeps
      const bool continued = step.has(j);  // its continuation already bounds its cost
      step.offer(j, best.cost + dur[b], best.back, true);
      if (!continued) cap.add(best.cost + dur[b]);
    }
  });
}

// Offers the joins into `targets` (the entries of `diviseme` when set, else any states).
// With beta = 0 (or no features) C drops out and the cheapest active wins every join.
void offer_joins(const PhoneGraph& graph, const std::vector<Active>& prev, std::span<const StateId> targets,
                 std::optional<Diviseme> diviseme, const SearchOptions& options, DurationTerm& duration, std::size_t t,
                 CapLimit& cap, StepBuilder& step, JoinScratch& scratch) {
  if (targets.empty() || prev.empty()) return;
  if (options.beta == 0.0 || !graph.has_junction_features()) {
    const auto best = std::min_element(prev.begin(), prev.end(), better);
    const auto back = static_cast<std::uint32_t>(best - prev.begin());
    for (StateId j : targets) step.offer(j, best->cost + 1.0 + duration(j, t), back, true);
    return;
  }
  if (!options.prune_joins) return offer_every_join(graph, prev, targets, options.beta, duration, t, step);
  offer_pruned_joins(graph, prev, targets, diviseme, options.beta, duration, t, options.max_active, cap, step,
                     scratch);
}

void prune(std::vector<Active>& actives, std::optional<std::size_t> cap) {
  if (!cap || actives.size() <= *cap) return;
  const auto keep = static_cast<std::ptrdiff_t>(std::max<std::size_t>(*cap, 1));
  std::nth_element(actives.begin(), actives.begin() + keep - 1, actives.end(), better);
  actives.resize(static_cast<std::size_t>(keep));
}

}  // namespace

SearchResult unit_search(const PhoneGraph& graph, std::span<const VisemeClass> targets,
                         const SearchOptions& options) {
  return unit_search(graph, targets, {}, options);
}

SearchResult unit_search(const PhoneGraph& graph, std::span<const VisemeClass> targets,
                         std::span<const std::int64_t> target_frames, const SearchOptions& options) {
  SearchResult result;
  if (!target_frames.empty() && target_frames.size() != targets.size())
    throw std::invalid_argument("unit search: " + std::to_string(target_frames.size()) + " target lengths for " +
                                std::to_string(targets.size()) + " target phones");
  if (targets.empty()) return result;
  if (options.beta < 0.0) throw std::invalid_argument("unit search: beta must be >= 0");
  if (!(options.duration_weight >= 0.0) || std::isinf(options.duration_weight))
    throw std::invalid_argument("unit search: the duration weight must be finite and >= 0");
  DurationTerm duration(graph, target_frames, options.duration_weight);
  for (std::size_t t = 0; t < targets.size(); ++t)
    if (graph.with_viseme(targets[t]).empty())
      throw std::invalid_argument("unit search: the voice has no phone of viseme class " +
                                  std::string(viseme_class_name(targets[t])) + " (target phone " +
                                  std::to_string(t) + ")");

  std::vector<std::vector<Active>> steps(targets.size());
  StepBuilder builder(graph.size());
  for (StateId j : graph.with_viseme(targets[0])) builder.offer(j, 1.0 + duration(j, 0), kNoBack, true);
  steps[0] = builder.take();
  prune(steps[0], options.max_active);
  result.stats.active_per_step.push_back(steps[0].size());

  CapLimit cap(options.max_active);
  JoinScratch scratch;
  for (std::size_t t = 1; t < targets.size(); ++t) {
    const auto& prev = steps[t - 1];
    cap.clear();
    // Within a recording: the next phone, free.
    for (std::uint32_t a = 0; a < prev.size(); ++a) {
      const StateId i = prev[a].state;
      if (graph.has_child(i) && graph.state(i + 1).viseme == targets[t]) {
        const double cost = prev[a].cost + duration(i + 1, t);
        builder.offer(i + 1, cost, a, false);
        cap.add(cost);
      }
    }
    // Across recordings: states whose parent looks like the phone we leave.
    offer_joins(graph, prev, graph.entries(targets[t - 1], targets[t]), Diviseme{targets[t - 1], targets[t]}, options,
                duration, t, cap, builder, scratch);
    steps[t] = builder.take();
    if (steps[t].empty()) {  // the voice never recorded this diviseme: join anywhere that matches
      ++result.stats.hard_joins;
      offer_joins(graph, prev, graph.with_viseme(targets[t]), std::nullopt, options, duration, t, cap, builder,
                  scratch);
      steps[t] = builder.take();
    }
    prune(steps[t], options.max_active);
    result.stats.active_per_step.push_back(steps[t].size());
  }

  // Back-trace from the cheapest final state.
  const auto& last = steps.back();
  std::uint32_t a = static_cast<std::uint32_t>(std::min_element(last.begin(), last.end(), better) - last.begin());
  result.cost = last[a].cost;
  result.states.resize(targets.size());
  std::vector<bool> joined(targets.size());
  for (std::size_t t = targets.size(); t-- > 0;) {
    result.states[t] = steps[t][a].state;
    joined[t] = steps[t][a].joined;
    a = steps[t][a].back;
  }
  for (std::size_t t = 0; t < targets.size(); ++t) {
    if (joined[t]) result.units.push_back({result.states[t], t, 0});
    ++result.units.back().length;
  }
  return result;
}

}  // namespace fapcast::synth
