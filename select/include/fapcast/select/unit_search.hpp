#pragma once
// Viterbi unit selection over the phone graph (paper section 3.7): the fewest, longest,
// best-joining runs of recorded phones that spell a target viseme sequence.
#include "fapcast/select/phone_graph.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace fapcast {

// The default values are what fapcast ships: `say`, `animate` and `eval synth` search with them
// unless told otherwise (spec/search.md: beta 0.1 and a cap of 64, chosen by spec/evaluation.md
// and the cap's cost in spec/search.md).
struct SearchOptions {
  // Weight of the smoothness term: a join costs 1 + beta * C. beta = 0 minimises the number
  // of units alone.
  double beta = 0.1;
  // Keep at most this many active states per target phone (the cheapest); nullopt = all. The
  // first phone keeps, beside them, every state whose recording goes on in the second phone's
  // class: all its states start at the same cost, and the cap alone would keep the lowest state
  // ids instead of the starts of long units.
  std::optional<std::size_t> max_active = 64;
  // Skip the joins that provably cannot win or survive the cap (spec/search.md, "Pruning the
  // joins"). The result is identical either way, to the bit; false evaluates every pair of
  // active state and entry state, the reference the tests and the benchmark compare against.
  bool prune_joins = true;
  // Weight of the duration term: state j serving a target phone of n_t frames adds
  // duration_weight * ln^2(n_j / n_t), n_j its recorded frames. The concatenation warps every phone to
  // its target's length, and a large warp distorts the timing of lip opening and closure most;
  // the term prefers units whose phones already last about as long. 0 = the paper's cost.
  double duration_weight = 0.0;
  // Weight of the right-context term: a join i -> j at target phone t adds context_weight when
  // the phone recorded after i (its child) is not of class targets[t], or i ends its recording.
  // The join rule (G = 0) makes the entered unit's left context right; this asks the same of the
  // unit left, whose last phone was recorded coarticulated with what followed it (a take's last
  // phone anticipates the rest after the word). 0 = the paper's cost; 0.3 (below one unit: it
  // never buys a unit, it chooses among paths of as many units) measured in spec/evaluation.md.
  double context_weight = 0.3;
  // Weight of the jaw term: state j serving target phone t adds jaw_weight * (a_j - w_t)^2, a_j
  // the jaw opening recorded in j and w_t the opening wanted at t, both in the caller's units
  // (SearchTargets). 0 = the paper's cost.
  double jaw_weight = 0.0;
};

// What the target terms weigh besides the classes (each span empty = that term off).
struct SearchTargets {
  std::span<const std::int64_t> frames;  // per target phone, its length in voice frames (>= 1)
  std::span<const float> jaw;            // per target phone, the jaw opening wanted
  std::span<const float> state_jaw;      // per graph state, the jaw opening recorded
};

// A run of consecutive states of one recording that covers consecutive target phones.
struct Unit {
  StateId first_state = 0;
  std::size_t first_target = 0;  // target phones [first_target, first_target + length)
  std::size_t length = 0;
  bool operator==(const Unit&) const = default;
};

struct SearchStats {
  std::vector<std::size_t> active_per_step;  // active states after pruning, per target phone
  std::size_t hard_joins = 0;  // steps where no admissible join existed (see unit_search)
};

struct SearchResult {
  std::vector<StateId> states;  // one per target phone
  std::vector<Unit> units;
  double cost = 0.0;  // number of units + beta * sum of join costs + the duration and context terms
  SearchStats stats;
};

// Finds the minimum-cost path. Transitions: to the next state of the same recording at cost 0;
// to a state j whose parent has the viseme of the state left (G = 0) at cost 1 + beta * C(i, j);
// a state matches target phone t only if its viseme is targets[t] (d = 0, else infinite), and
// costs its duration term (SearchOptions::duration_weight) there; a join from i at target phone t
// also costs the context term (SearchOptions::context_weight) when i's own recording does not go on
// in class targets[t].
// Starting costs 1 (the first unit). When some step has no admissible join at all, the search
// joins into any state of the right viseme (a "hard join", counted in stats) rather than fail.
// Throws std::invalid_argument naming the first target viseme class the graph has no state of.
SearchResult unit_search(const PhoneGraph& graph, std::span<const VisemeClass> targets,
                         const SearchOptions& options = {});
// The same with each target's length in voice frames (>= 1 each, one per target), which the
// duration term weighs (none without lengths). Throws std::invalid_argument when the lengths do
// not match the targets or one is below 1 while the term is on.
SearchResult unit_search(const PhoneGraph& graph, std::span<const VisemeClass> targets,
                         std::span<const std::int64_t> target_frames, const SearchOptions& options);
// The same with every target term's inputs.
SearchResult unit_search(const PhoneGraph& graph, std::span<const VisemeClass> targets,
                         const SearchTargets& shape, const SearchOptions& options);

}  // namespace fapcast
