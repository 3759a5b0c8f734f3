#include "fapcast/math/greedy_cover.hpp"

#include <queue>
#include <stdexcept>

namespace fapcast {

std::vector<GreedyPick> greedy_cover(const std::vector<std::vector<std::uint32_t>>& candidates,
                                     std::span<const double> unit_weight,
                                     std::vector<bool>& covered, std::size_t max_picks) {
  if (covered.size() != unit_weight.size()) throw std::invalid_argument("greedy_cover: covered/weights size mismatch");
  const auto gain_of = [&](std::size_t c) {
    double gain = 0.0;
    std::vector<std::uint32_t> seen;
    for (std::uint32_t u : candidates[c]) {
      if (u >= unit_weight.size()) throw std::invalid_argument("greedy_cover: unit id out of range");
      if (covered[u]) continue;
      bool dup = false;
      for (std::uint32_t s : seen) dup = dup || s == u;
      if (!dup) { gain += unit_weight[u]; seen.push_back(u); }
    }
    return gain;
  };
  // Lazy greedy: gains only shrink as units get covered, so a stale gain is an upper bound;
  // re-evaluate the top until it is fresh. Ties go to the lower candidate index.
  struct Entry { double gain; std::size_t candidate; std::size_t round; };
  const auto worse = [](const Entry& a, const Entry& b) {
    return a.gain < b.gain || (a.gain == b.gain && a.candidate > b.candidate);
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(worse)> queue(worse);
  for (std::size_t c = 0; c < candidates.size(); ++c) queue.push({gain_of(c), c, 0});
  std::vector<GreedyPick> picks;
  while (picks.size() < max_picks && !queue.empty()) {
    Entry top = queue.top();
    queue.pop();
    if (top.round != picks.size()) {
      top.gain = gain_of(top.candidate);
      top.round = picks.size();
      queue.push(top);
      continue;
    }
    if (top.gain <= 0.0) break;
    picks.push_back({top.candidate, top.gain});
    for (std::uint32_t u : candidates[top.candidate]) covered[u] = true;
  }
  return picks;
}

}  // namespace fapcast
