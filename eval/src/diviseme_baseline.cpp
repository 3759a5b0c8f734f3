#include "fapcast/eval/diviseme_baseline.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fapcast {
namespace {

std::string where(std::size_t t) { return "diviseme baseline: target phone " + std::to_string(t); }

void check_targets(std::span<const TargetPhone> targets) {
  if (targets.size() < 2)
    throw std::invalid_argument("diviseme baseline: " + std::to_string(targets.size()) +
                                " target phones; a diviseme needs two");
  for (std::size_t t = 0; t < targets.size(); ++t)
    if (targets[t].end_frame <= targets[t].first_frame) throw std::invalid_argument(where(t) + " spans no frames");
}

// How far a recorded phone's duration is from a target's, on a log scale (so halving and
// doubling cost the same).
double duration_mismatch(const FrameSpan& recorded, const TargetPhone& target) {
  const double r = std::log(static_cast<double>(std::max<std::uint32_t>(recorded.count, 1)) /
                            static_cast<double>(target.end_frame - target.first_frame));
  return r * r;
}

// The best-matching single state of the target's class (the fallback of an unrecorded pair).
StateId best_single(const PhoneGraph& graph, std::span<const TargetPhone> targets, std::size_t t) {
  const auto candidates = graph.with_viseme(targets[t].viseme);
  if (candidates.empty())
    throw std::invalid_argument(where(t) + ": the voice has no phone of viseme class '" +
                                std::string(viseme_class_name(targets[t].viseme)) + "'");
  StateId best = candidates.front();
  double best_cost = std::numeric_limits<double>::infinity();
  for (const StateId j : candidates) {
    const double cost = duration_mismatch(graph.state(j).frames, targets[t]);
    if (cost < best_cost || (cost == best_cost && j < best)) best = j, best_cost = cost;
  }
  return best;
}

// First and second half of a span of `count` frames starting at `first`: ceil(count / 2) frames
// each, so an odd span shares its centre frame and a one-frame span is both halves.
std::pair<FrameSpan, FrameSpan> halves(const FrameSpan& s) {
  const std::uint32_t h = (s.count + 1) / 2;
  return {{s.first, h}, {s.first + s.count / 2, h}};
}

}  // namespace

DivisemeSelection select_divisemes(const PhoneGraph& graph, std::span<const TargetPhone> targets,
                                   DivisemeChoiceRule rule) {
  check_targets(targets);
  DivisemeSelection selection;
  selection.divisemes.reserve(targets.size() - 1);
  for (std::size_t t = 0; t + 1 < targets.size(); ++t) {
    // entries(a, b): states of class b whose parent is of class a - exactly the second phones of
    // every recorded a-b pair.
    const auto seconds = graph.entries(targets[t].viseme, targets[t + 1].viseme);
    DivisemeChoice best;
    double best_cost = std::numeric_limits<double>::infinity();
    for (const StateId j : seconds) {
      const double cost = rule == DivisemeChoiceRule::kFirst
                              ? 0.0
                              : duration_mismatch(graph.state(j - 1).frames, targets[t]) +
                                    duration_mismatch(graph.state(j).frames, targets[t + 1]);
      if (cost < best_cost || (cost == best_cost && j - 1 < best.first_state))
        best = {j - 1, j, true}, best_cost = cost;
    }
    if (seconds.empty()) {
      best = {best_single(graph, targets, t), best_single(graph, targets, t + 1), false};
      ++selection.unrecorded;
    }
    selection.divisemes.push_back(best);
  }
  return selection;
}

Eigen::MatrixXf concatenate_divisemes(const PhoneGraph& graph, const PcaFrames& pca_frames,
                                 const DivisemeSelection& selection,
                                 std::span<const TargetPhone> targets, const ConcatenationOptions& options) {
  check_targets(targets);
  const std::size_t T = targets.size();
  if (selection.divisemes.size() != T - 1)
    throw std::invalid_argument("diviseme baseline: " + std::to_string(selection.divisemes.size()) +
                                " divisemes for " + std::to_string(T) + " target phones");
  for (std::size_t t = 0; t + 1 < T; ++t) {
    const auto& d = selection.divisemes[t];
    if (d.first_state >= graph.size() || d.second_state >= graph.size() ||
        graph.state(d.first_state).viseme != targets[t].viseme ||
        graph.state(d.second_state).viseme != targets[t + 1].viseme ||
        (d.recorded && (d.second_state != d.first_state + 1 || !graph.has_child(d.first_state))))
      throw std::invalid_argument("diviseme baseline: diviseme " + std::to_string(t) +
                                  " does not fit the graph or the targets");
  }

  // The half-phone graph: state j becomes 2j (first half) and 2j + 1 (second half), in the same
  // recording, so concatenate_units' warp of a half reads the recording on either side of the cut.
  std::vector<PhoneState> half_states;
  half_states.reserve(2 * graph.size());
  for (const auto& s : graph.states()) {
    const auto [a, b] = halves(s.frames);
    half_states.push_back({s.utterance, s.viseme, a});
    half_states.push_back({s.utterance, s.viseme, b});
  }
  const PhoneGraph half_graph(std::move(half_states));

  // Half targets, each with its state and the unit it belongs to. A unit is one diviseme; an
  // unrecorded diviseme is two units (its halves come from different recordings).
  std::vector<TargetPhone> half_targets;
  SearchResult result;
  std::pair<std::size_t, int> unit_key{T, -1};
  auto add = [&](const TargetPhone& target, std::int64_t first, std::int64_t end, std::size_t owner,
                 std::size_t phone, StateId half_state) {
    if (end <= first) return;
    const auto& d = selection.divisemes[owner];
    const std::pair<std::size_t, int> key{owner, d.recorded ? 0 : static_cast<int>(phone - owner)};
    if (key != unit_key) {
      result.units.push_back({half_state, half_targets.size(), 0});
      unit_key = key;
    }
    ++result.units.back().length;
    half_targets.push_back({target.viseme, first, end, target.hold});
    result.states.push_back(half_state);
  };
  for (std::size_t t = 0; t < T; ++t) {
    const auto& target = targets[t];
    const std::int64_t middle = target.first_frame + (target.end_frame - target.first_frame + 1) / 2;
    const std::size_t before = t == 0 ? 0 : t - 1;  // the diviseme that ends in phone t
    const std::size_t after = t + 1 == T ? T - 2 : t;  // the one that starts there
    const auto& db = selection.divisemes[before];
    const auto& da = selection.divisemes[after];
    add(target, target.first_frame, middle, before, t, 2 * (t == 0 ? db.first_state : db.second_state));
    add(target, middle, target.end_frame, after, t, 2 * (t + 1 == T ? da.second_state : da.first_state) + 1);
  }
  result.cost = static_cast<double>(result.units.size());
  // A diviseme's cuts already lie in the middle of phones (half-states here): its units take over
  // at their own first half-state, never half a half-phone earlier.
  ConcatenationOptions at_cuts = options;
  at_cuts.join_mid_phone = false;
  return concatenate_units(half_graph, pca_frames, result, half_targets, at_cuts);
}

}  // namespace fapcast
