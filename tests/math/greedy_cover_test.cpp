// Greedy coverage: on random instances every pick adds the most new weight of any candidate
// (ties to the earliest), and the result covers everything coverable.
#include "fapcast/math/greedy_cover.hpp"
#include "support/test_seed.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace fapcast {
namespace {

double gain(const std::vector<std::uint32_t>& c, const std::vector<double>& w, const std::vector<bool>& covered) {
  std::set<std::uint32_t> units(c.begin(), c.end());
  double g = 0;
  for (auto u : units) if (!covered[u]) g += w[u];
  return g;
}

TEST(GreedyCover, EachPickHasTheLargestGainOnRandomInstances) {
  const std::uint64_t seed = test::test_seed(20060401);
  SCOPED_TRACE(test::reproduce_hint(seed));
  std::mt19937 rng(static_cast<std::mt19937::result_type>(seed));
  for (int instance = 0; instance < 50; ++instance) {
    const std::size_t units = 1 + rng() % 60, count = 1 + rng() % 40;
    std::vector<double> weight(units);
    for (auto& w : weight) w = (rng() % 4 == 0) ? 1.0 : static_cast<double>(rng() % 100);
    std::vector<std::vector<std::uint32_t>> candidates(count);
    for (auto& c : candidates) {
      const std::size_t n = rng() % 6;
      for (std::size_t k = 0; k < n; ++k) c.push_back(static_cast<std::uint32_t>(rng() % units));
    }
    std::vector<bool> covered(units, false);
    for (std::size_t u = 0; u < units; ++u) covered[u] = rng() % 10 == 0;
    std::vector<bool> check = covered;
    const auto picks = greedy_cover(candidates, weight, covered, count);
    for (const GreedyPick& p : picks) {
      double best = 0;
      std::size_t best_index = 0;
      for (std::size_t c = 0; c < count; ++c) {
        const double g = gain(candidates[c], weight, check);
        if (g > best) { best = g; best_index = c; }
      }
      ASSERT_EQ(p.candidate, best_index) << "instance " << instance;
      ASSERT_DOUBLE_EQ(p.gain, best);
      for (auto u : candidates[p.candidate]) check[u] = true;
    }
    EXPECT_EQ(check, covered);
    for (std::size_t c = 0; c < count; ++c) EXPECT_EQ(gain(candidates[c], weight, covered), 0.0);
  }
}

TEST(GreedyCover, RespectsMaxPicksAndRejectsBadIds) {
  std::vector<bool> covered(3, false);
  const std::vector<double> w{1, 2, 3};
  const auto picks = greedy_cover({{0}, {1}, {2}}, w, covered, 2);
  EXPECT_EQ(picks, (std::vector<GreedyPick>{{2, 3.0}, {1, 2.0}}));
  EXPECT_THROW(greedy_cover({{7}}, w, covered, 1), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
