#include "fapcast/synth/unit_search.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace fapcast::synth {
namespace {

constexpr std::uint32_t kNoBack = std::numeric_limits<std::uint32_t>::max();

// One active state at one target phone: its best cost so far and where that came from.
struct Active {
  StateId state;
  double cost;
  std::uint32_t back;  // index into the previous step's actives
  bool joined;         // arrived by a join (a new unit starts here)
};

// Deterministic order: cheaper first, then lower state id.
bool better(const Active& a, const Active& b) {
  return a.cost < b.cost || (a.cost == b.cost && a.state < b.state);
}

// The actives of one step, at most one entry per state, with O(1) lookup by state.
class StepBuilder {
 public:
  explicit StepBuilder(std::size_t states) : slot_(states, kNoBack) {}

  void offer(StateId j, double cost, std::uint32_t back, bool joined) {
    std::uint32_t& s = slot_[j];
    if (s == kNoBack) {
      s = static_cast<std::uint32_t>(out_.size());
      out_.push_back({j, cost, back, joined});
    } else if (cost < out_[s].cost) {
      out_[s] = {j, cost, back, joined};
    }
  }

  // How many offers so far cost strictly less than `bound`.
  std::size_t count_below(double bound) const {
    return static_cast<std::size_t>(std::count_if(
        out_.begin(), out_.end(), [bound](const Active& a) { return a.cost < bound; }));
  }

  std::vector<Active> take() {
    for (const auto& a : out_) slot_[a.state] = kNoBack;
    return std::exchange(out_, {});
  }

 private:
  std::vector<std::uint32_t> slot_;  // state -> index in out_, kNoBack when absent
  std::vector<Active> out_;
};

// Offers every state in `targets` as a join from the cheapest predecessor, counting
// 1 + beta * C(i, j). With beta = 0 (or no features) C drops out and the cheapest actives win.
void offer_joins(const PhoneGraph& graph, const std::vector<Active>& prev,
                 std::span<const StateId> targets, double beta, StepBuilder& step) {
  if (targets.empty() || prev.empty()) return;
  if (beta == 0.0 || !graph.has_junction_features()) {
    const auto best = std::min_element(prev.begin(), prev.end(), better);
    const auto back = static_cast<std::uint32_t>(best - prev.begin());
    for (StateId j : targets) step.offer(j, best->cost + 1.0, back, true);
    return;
  }
  // C(i, j) = |entry_j - exit_i|^2 / 2 for all pairs at once: |e|^2 + |x|^2 - 2 e.x.
  const auto& f = graph.junction();
  const auto dims = f.entry.cols();
  Eigen::MatrixXf exits(static_cast<Eigen::Index>(prev.size()), dims);
  Eigen::MatrixXf entries(static_cast<Eigen::Index>(targets.size()), dims);
  for (std::size_t a = 0; a < prev.size(); ++a) exits.row(static_cast<Eigen::Index>(a)) = f.exit.row(prev[a].state);
  for (std::size_t b = 0; b < targets.size(); ++b) entries.row(static_cast<Eigen::Index>(b)) = f.entry.row(targets[b]);
  Eigen::MatrixXf cross = entries * exits.transpose();  // targets x prev
  const Eigen::VectorXf en = entries.rowwise().squaredNorm();
  const Eigen::VectorXf ex = exits.rowwise().squaredNorm();
  for (std::size_t b = 0; b < targets.size(); ++b) {
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t back = 0;
    for (std::size_t a = 0; a < prev.size(); ++a) {
      const auto bi = static_cast<Eigen::Index>(b), ai = static_cast<Eigen::Index>(a);
      const float c = std::max(0.0f, 0.5f * (en(bi) + ex(ai) - 2.0f * cross(bi, ai)));
      const double cost = prev[a].cost + 1.0 + beta * c;
      if (cost < best) best = cost, back = static_cast<std::uint32_t>(a);
    }
    step.offer(targets[b], best, back, true);
  }
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
  SearchResult result;
  if (targets.empty()) return result;
  if (options.beta < 0.0) throw std::invalid_argument("unit search: beta must be >= 0");
  for (std::size_t t = 0; t < targets.size(); ++t)
    if (graph.with_viseme(targets[t]).empty())
      throw std::invalid_argument("unit search: the voice has no phone of viseme class " +
                                  std::string(viseme_class_name(targets[t])) + " (target phone " +
                                  std::to_string(t) + ")");

  std::vector<std::vector<Active>> steps(targets.size());
  StepBuilder builder(graph.size());
  for (StateId j : graph.with_viseme(targets[0])) builder.offer(j, 1.0, kNoBack, true);
  steps[0] = builder.take();
  prune(steps[0], options.max_active);
  result.stats.active_per_step.push_back(steps[0].size());

  for (std::size_t t = 1; t < targets.size(); ++t) {
    const auto& prev = steps[t - 1];
    // Within a recording: the next phone, free.
    for (std::uint32_t a = 0; a < prev.size(); ++a) {
      const StateId i = prev[a].state;
      if (graph.has_child(i) && graph.state(i + 1).viseme == targets[t])
        builder.offer(i + 1, prev[a].cost, a, false);
    }
    // Across recordings: states whose parent looks like the phone we leave. Every join costs at
    // least the cheapest previous cost + 1, so when the cap is already filled by continuations
    // strictly cheaper than that, no join can survive pruning: skip them (exact, and the common
    // case inside long units, where the junction costs dominate the search time).
    const double join_floor =
        std::min_element(prev.begin(), prev.end(), better)->cost + 1.0;
    if (!options.max_active ||
        builder.count_below(join_floor) < std::max<std::size_t>(*options.max_active, 1))
      offer_joins(graph, prev, graph.entries(targets[t - 1], targets[t]), options.beta, builder);
    steps[t] = builder.take();
    if (steps[t].empty()) {  // the voice never recorded this diviseme: join anywhere that matches
      ++result.stats.hard_joins;
      offer_joins(graph, prev, graph.with_viseme(targets[t]), options.beta, builder);
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
