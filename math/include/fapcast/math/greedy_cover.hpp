#pragma once
// Greedy weighted set cover: repeatedly pick the candidate that adds the most weight of units
// not yet covered (ties: the earliest candidate). The classic (1 - 1/e) approximation; the
// recording script uses it for syllables and divisemes.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace fapcast {

struct GreedyPick {
  std::size_t candidate;  // index into the candidate list
  double gain;            // weight of the units it newly covered (> 0)
  friend bool operator==(const GreedyPick&, const GreedyPick&) = default;
};

// Picks up to `max_picks` candidates (each a list of unit ids < unit_weight.size(); duplicates
// inside a candidate count once). `covered` holds units already covered (updated in place).
// Stops early when no candidate adds positive weight. Candidates already picked are skipped.
std::vector<GreedyPick> greedy_cover(const std::vector<std::vector<std::uint32_t>>& candidates,
                                     std::span<const double> unit_weight,
                                     std::vector<bool>& covered, std::size_t max_picks);

}  // namespace fapcast
