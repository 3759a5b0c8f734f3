// The Viterbi unit search against brute force on small random graphs, and its contracts.
#include "fapcast/select/unit_search.hpp"
#include "support/synthetic_voice_graph.hpp"
#include "support/test_seed.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

namespace fapcast {
namespace {

VisemeClass V(int i) { return static_cast<VisemeClass>(i); }

std::vector<VisemeClass> Vs(std::initializer_list<int> classes) {
  std::vector<VisemeClass> out;
  for (int c : classes) out.push_back(V(c));
  return out;
}

// The default seed of the random search tests (support/test_seed.hpp).
constexpr std::uint64_t kSearchSeed = 20061;

// Utterances given as viseme strings; each phone one frame long, PCA frames random.
struct Toy {
  std::vector<PhoneState> states;
  Eigen::MatrixXf frames;
};

// With `max_frames_per_phone` above `frames_per_phone`, each phone lasts a random count between.
Toy make_toy(const std::vector<std::vector<int>>& utterances, std::mt19937_64& rng, int k = 3,
             int frames_per_phone = 2, int max_frames_per_phone = 0) {
  Toy toy;
  std::uniform_int_distribution<int> count(frames_per_phone, std::max(frames_per_phone, max_frames_per_phone));
  std::uint32_t f = 0;
  for (std::uint32_t u = 0; u < utterances.size(); ++u)
    for (int v : utterances[u]) {
      const auto n = static_cast<std::uint32_t>(max_frames_per_phone > frames_per_phone ? count(rng) : frames_per_phone);
      toy.states.push_back({u, V(v), {f, n}});
      f += n;
    }
  std::normal_distribution<float> normal;
  toy.frames = Eigen::MatrixXf(f, k);
  for (Eigen::Index i = 0; i < toy.frames.size(); ++i) toy.frames.data()[i] = normal(rng);
  return toy;
}

// The duration term on the paper's cost otherwise (no context term).
SearchOptions with_duration(double beta, double weight) {
  SearchOptions o;
  o.beta = beta;
  o.duration_weight = weight;
  o.context_weight = 0.0;
  return o;
}

// The duration term as SearchOptions defines it, written out independently of the search.
double duration_term(const PhoneGraph& g, StateId j, std::int64_t target_frames, double weight) {
  const double r = std::log(static_cast<double>(g.state(j).frames.count) / static_cast<double>(target_frames));
  return weight * r * r;
}

// Minimum cost over every admissible state sequence, or +inf when there is none; with `lengths`,
// each state also pays its duration term at `weight`.
// A join from i at target t also pays `context` when i's recording does not go on in class targets[t].
// With `jaw`, each state also pays jaw_weight * (state_jaw[j] - jaw[t])^2.
double brute_force(const PhoneGraph& g, std::span<const VisemeClass> targets, double beta, double weight = 0.0,
                   std::span<const std::int64_t> lengths = {}, double context = 0.0,
                   std::span<const float> state_jaw = {}, std::span<const float> jaw = {}, double jaw_weight = 0.0) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<StateId> path;
  std::function<void(std::size_t, double)> go = [&](std::size_t t, double cost) {
    if (t == targets.size()) {
      best = std::min(best, cost);
      return;
    }
    for (StateId j = 0; j < g.size(); ++j) {
      if (g.state(j).viseme != targets[t]) continue;
      double step;
      if (t == 0) {
        step = 1.0;
      } else {
        const StateId i = path.back();
        const bool next_in_recording = g.has_child(i) && j == i + 1;
        const bool admissible_join = g.has_parent(j) && g.state(j - 1).viseme == g.state(i).viseme;
        if (next_in_recording) step = 0.0;
        else if (admissible_join)
          step = 1.0 + beta * join_cost(g, i, j) +
                 (g.has_child(i) && g.state(i + 1).viseme == targets[t] ? 0.0 : context);
        else continue;
      }
      if (!lengths.empty()) step += duration_term(g, j, lengths[t], weight);
      if (!jaw.empty()) step += jaw_weight * std::pow(static_cast<double>(state_jaw[j]) - static_cast<double>(jaw[t]), 2);
      path.push_back(j);
      go(t + 1, cost + step);
      path.pop_back();
    }
  };
  go(0, 0.0);
  return best;
}

// A path's cost written out term by term (no context term): its units, its joins, and each state's
// duration and jaw terms.
double written_out_cost(const PhoneGraph& g, const SearchResult& r, const SearchOptions& options,
                        std::span<const std::int64_t> lengths, std::span<const float> state_jaw = {},
                        std::span<const float> jaw = {}) {
  double path = static_cast<double>(r.units.size());
  for (std::size_t t = 0; t < r.states.size(); ++t) {
    path += duration_term(g, r.states[t], lengths[t], options.duration_weight);
    if (!jaw.empty()) path += options.jaw_weight * std::pow(static_cast<double>(state_jaw[r.states[t]]) - jaw[t], 2);
    if (t > 0 && r.states[t] != r.states[t - 1] + 1) path += options.beta * join_cost(g, r.states[t - 1], r.states[t]);
  }
  return path;
}

// Two takes of one word, classes 0 1 0, still frames (every join costs 0): the vowel lasts
// `first_vowel` frames in the first take, `second_vowel` in the second; the rests 3 each.
PhoneGraph two_takes_of_one_word(std::uint32_t first_vowel, std::uint32_t second_vowel) {
  std::vector<PhoneState> states;
  std::uint32_t at = 0;
  for (std::uint32_t take = 0; take < 2; ++take)
    for (const auto& [v, n] : {std::pair{0, 3u}, std::pair{1, take == 0 ? first_vowel : second_vowel}, std::pair{0, 3u}}) {
      states.push_back({take, V(v), {at, n}});
      at += n;
    }
  return PhoneGraph(states, join_features(states, Eigen::MatrixXf::Zero(at, 2)));
}

// A small random graph whose phones last 1-6 frames, and 1-5 random target phones of 1-9 frames.
struct TimedSearch {
  PhoneGraph graph;
  std::vector<VisemeClass> targets;
  std::vector<std::int64_t> lengths;
  bool covered = true;  // the graph has a state of every target class
};
TimedSearch random_timed_search(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> visemes(0, 2), length(2, 5), count(2, 4), tlen(1, 5), frames(1, 9);
  std::vector<std::vector<int>> utts(static_cast<std::size_t>(count(rng)));
  for (auto& u : utts) {
    u.resize(static_cast<std::size_t>(length(rng)));
    for (auto& v : u) v = visemes(rng);
  }
  const Toy toy = make_toy(utts, rng, 3, 1, 6);
  TimedSearch out{PhoneGraph(toy.states, join_features(toy.states, toy.frames)), {}, {}};
  out.targets.resize(static_cast<std::size_t>(tlen(rng)));
  out.lengths.resize(out.targets.size());
  for (auto& v : out.targets) v = V(visemes(rng));
  for (auto& n : out.lengths) n = frames(rng);
  for (auto v : out.targets) out.covered = out.covered && !out.graph.with_viseme(v).empty();
  return out;
}

// (beta, context weight): the paper's cost (context 0) and with the right-context term.
class UnitSearchBruteForce : public ::testing::TestWithParam<std::tuple<double, double>> {};

TEST_P(UnitSearchBruteForce, FindsTheMinimumCostOnRandomSmallGraphs) {
  const auto [beta, context] = GetParam();
  const auto seed = test::test_seed(kSearchSeed);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> visemes(0, 2), length(2, 5), count(2, 4), tlen(1, 5);
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::vector<int>> utts(static_cast<std::size_t>(count(rng)));
    for (auto& u : utts) {
      u.resize(static_cast<std::size_t>(length(rng)));
      for (auto& v : u) v = visemes(rng);
    }
    const Toy toy = make_toy(utts, rng);
    const PhoneGraph g(toy.states, join_features(toy.states, toy.frames));
    std::vector<VisemeClass> targets(static_cast<std::size_t>(tlen(rng)));
    for (auto& v : targets) v = V(visemes(rng));
    bool covered = true;
    for (auto v : targets) covered = covered && !g.with_viseme(v).empty();
    if (!covered) {
      EXPECT_THROW(unit_search(g, targets, {beta, {}}), std::invalid_argument);
      continue;
    }
    const double expected = brute_force(g, targets, beta, 0.0, {}, context);
    SearchOptions options{beta, {}};
    options.context_weight = context;
    const SearchResult r = unit_search(g, targets, options);
    if (std::isinf(expected)) {
      EXPECT_GT(r.stats.hard_joins, 0u) << "no admissible path exists, so a hard join is needed";
      continue;
    }
    ++compared;
    ASSERT_NEAR(r.cost, expected, 1e-4 * (1 + expected))
        << "trial " << trial << "; " << test::reproduce_hint(seed);
    EXPECT_EQ(r.stats.hard_joins, 0u);
    // The path is real: visemes match and units are runs within one recording.
    ASSERT_EQ(r.states.size(), targets.size());
    for (std::size_t t = 0; t < targets.size(); ++t) EXPECT_EQ(g.state(r.states[t]).viseme, targets[t]);
    std::size_t covered_targets = 0;
    for (const Unit& u : r.units) {
      EXPECT_EQ(u.first_target, covered_targets);
      for (std::size_t n = 0; n < u.length; ++n) EXPECT_EQ(r.states[u.first_target + n], u.first_state + n);
      covered_targets += u.length;
    }
    EXPECT_EQ(covered_targets, targets.size());
    if (beta == 0.0 && context == 0.0) {
      EXPECT_EQ(r.cost, static_cast<double>(r.units.size())) << "beta = 0 counts units";
    }
  }
  EXPECT_GT(compared, 100) << "too few comparable trials to mean anything";
}

INSTANTIATE_TEST_SUITE_P(BetasAndContext, UnitSearchBruteForce,
                         ::testing::Combine(::testing::Values(0.0, 0.05, 1.0), ::testing::Values(0.0, 0.3)));

// The duration term: phones of random lengths, targets of random lengths; the search's cost is
// the brute-force minimum, and its path's cost written out term by term is that cost.
TEST(UnitSearch, DurationTermFindsTheMinimumCostOnRandomSmallGraphs) {
  const auto seed = test::test_seed(kSearchSeed);
  std::mt19937_64 rng(seed);
  int compared = 0, moved = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const TimedSearch timed = random_timed_search(rng);
    if (!timed.covered) continue;
    const PhoneGraph& g = timed.graph;
    const auto& targets = timed.targets;
    const auto& lengths = timed.lengths;
    const double beta = trial % 2 ? 0.05 : 0.0, weight = 0.5;
    const double expected = brute_force(g, targets, beta, weight, lengths);
    if (std::isinf(expected)) continue;
    const SearchResult r = unit_search(g, targets, lengths, with_duration(beta, weight));
    const std::string where = "trial " + std::to_string(trial) + "; " + test::reproduce_hint(seed);
    ASSERT_NEAR(r.cost, expected, 1e-9 * (1 + expected)) << where;
    for (std::size_t t = 0; t < targets.size(); ++t) ASSERT_EQ(g.state(r.states[t]).viseme, targets[t]) << where;
    EXPECT_NEAR(written_out_cost(g, r, with_duration(beta, weight), lengths), r.cost, 1e-9 * (1 + r.cost)) << where;
    ++compared;
    moved += unit_search(g, targets, lengths, with_duration(beta, 0.0)).states != r.states;
  }
  EXPECT_GT(compared, 100) << "too few comparable trials to mean anything";
  EXPECT_GT(moved, 10) << "the duration term never changed a path: the trials do not exercise it";
}

// Two recordings of the same word, one with its vowel as long as the target's: the term picks it;
// without the term the search takes the first (lowest state ids) as ties are broken.
TEST(UnitSearch, DurationTermPrefersTheUnitThatNeedsLessWarping) {
  const PhoneGraph g = two_takes_of_one_word(2, 12);
  const std::vector<VisemeClass> targets = Vs({0, 1, 0});
  const std::vector<std::int64_t> lengths{3, 11, 3};
  const SearchResult plain = unit_search(g, targets, lengths, with_duration(0.1, 0.0));
  EXPECT_EQ(plain.states, (std::vector<StateId>{0, 1, 2}));
  EXPECT_EQ(plain.cost, 1.0);
  const SearchResult timed = unit_search(g, targets, lengths, with_duration(0.1, 1.0));
  EXPECT_EQ(timed.states, (std::vector<StateId>{3, 4, 5}));
  const double r = std::log(12.0 / 11.0);
  EXPECT_DOUBLE_EQ(timed.cost, 1.0 + r * r);
}

TEST(UnitSearch, DurationTermRejectsBadLengthsAndWeights) {
  std::mt19937_64 rng(7);
  const Toy toy = make_toy({{0, 1}}, rng);
  const PhoneGraph g(toy.states, join_features(toy.states, toy.frames));
  const std::vector<VisemeClass> targets = Vs({0, 1});
  const std::vector<std::int64_t> one{4}, zero{4, 0}, good{4, 5};
  EXPECT_THROW(unit_search(g, targets, one, with_duration(0.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(unit_search(g, targets, zero, with_duration(0.0, 1.0)), std::invalid_argument);
  EXPECT_NO_THROW(unit_search(g, targets, zero, {}));  // the term is off: lengths are not read
  EXPECT_THROW(unit_search(g, targets, good, with_duration(0.0, -1.0)), std::invalid_argument);
  EXPECT_THROW(unit_search(g, targets, good, with_duration(0.0, std::numeric_limits<double>::infinity())),
               std::invalid_argument);
  EXPECT_THROW(unit_search(g, targets, good, with_duration(0.0, std::nan(""))), std::invalid_argument);
}

// The jaw term: every state has a recorded opening, every target a wanted one; the search's cost
// is the brute-force minimum (with the duration and context terms on as well), and its path's
// cost written out term by term is that cost.
TEST(UnitSearch, JawTermFindsTheMinimumCostOnRandomSmallGraphs) {
  const auto seed = test::test_seed(kSearchSeed);
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> opening;
  int compared = 0, moved = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const TimedSearch timed = random_timed_search(rng);
    const PhoneGraph& g = timed.graph;
    const auto& targets = timed.targets;
    const auto& lengths = timed.lengths;
    std::vector<float> jaw(targets.size()), state_jaw(g.size());
    for (auto& a : jaw) a = opening(rng);
    for (auto& a : state_jaw) a = opening(rng);
    if (!timed.covered) continue;
    SearchOptions options = with_duration(trial % 2 ? 0.05 : 0.0, trial % 3 == 0 ? 0.5 : 0.0);
    options.context_weight = trial % 4 == 0 ? 0.3 : 0.0;
    options.jaw_weight = 0.4;
    const double expected = brute_force(g, targets, options.beta, options.duration_weight, lengths,
                                        options.context_weight, state_jaw, jaw, options.jaw_weight);
    if (std::isinf(expected)) continue;
    const SearchResult r = unit_search(g, targets, SearchTargets{lengths, jaw, state_jaw}, options);
    const std::string where = "trial " + std::to_string(trial) + "; " + test::reproduce_hint(seed);
    ASSERT_NEAR(r.cost, expected, 1e-9 * (1 + expected)) << where;
    if (options.context_weight == 0.0) {
      EXPECT_NEAR(written_out_cost(g, r, options, lengths, state_jaw, jaw), r.cost, 1e-9 * (1 + r.cost)) << where;
    }
    ++compared;
    options.jaw_weight = 0.0;
    moved += unit_search(g, targets, SearchTargets{lengths, jaw, state_jaw}, options).states != r.states;
  }
  EXPECT_GT(compared, 100) << "too few comparable trials to mean anything";
  EXPECT_GT(moved, 10) << "the jaw term never changed a path: the trials do not exercise it";
}

// Two recordings of the same word, the second with its vowel's jaw as open as wanted: without the
// term the search takes the first (lowest state ids, as ties are broken), with it the second.
TEST(UnitSearch, JawTermPrefersTheUnitWhoseJawIsWanted) {
  const PhoneGraph g = two_takes_of_one_word(3, 3);
  const std::vector<VisemeClass> targets = Vs({0, 1, 0});
  const std::vector<float> state_jaw{0.f, -1.f, 0.f, 0.f, 1.f, 0.f}, jaw{0.f, 1.f, 0.f};
  SearchOptions options = with_duration(0.1, 0.0);
  EXPECT_EQ(unit_search(g, targets, SearchTargets{{}, jaw, state_jaw}, options).states, (std::vector<StateId>{0, 1, 2}))
      << "off, the tie goes to the lowest state ids";
  options.jaw_weight = 0.5;
  const SearchResult r = unit_search(g, targets, SearchTargets{{}, jaw, state_jaw}, options);
  EXPECT_EQ(r.states, (std::vector<StateId>{3, 4, 5}));
  EXPECT_DOUBLE_EQ(r.cost, 1.0);
}

TEST(UnitSearch, JawTermRejectsBadInputsAndWeights) {
  std::mt19937_64 rng(7);
  const Toy toy = make_toy({{0, 1}}, rng);
  const PhoneGraph g(toy.states, join_features(toy.states, toy.frames));
  const std::vector<VisemeClass> targets = Vs({0, 1});
  const std::vector<float> jaw{0.f, 1.f}, short_jaw{0.f}, state_jaw(g.size(), 0.f), short_states(g.size() - 1, 0.f);
  SearchOptions options;
  options.jaw_weight = 1.0;
  EXPECT_NO_THROW(unit_search(g, targets, SearchTargets{{}, jaw, state_jaw}, options));
  EXPECT_THROW(unit_search(g, targets, SearchTargets{{}, short_jaw, state_jaw}, options), std::invalid_argument);
  EXPECT_THROW(unit_search(g, targets, SearchTargets{{}, jaw, short_states}, options), std::invalid_argument);
  for (double bad : {-1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    options.jaw_weight = bad;
    EXPECT_THROW(unit_search(g, targets, SearchTargets{{}, jaw, state_jaw}, options), std::invalid_argument) << bad;
  }
}

// The pruned joins against the reference with the jaw term on (random openings, every cap).
TEST(UnitSearch, PrunedJoinsGiveTheReferenceResultWithTheJawTerm) {
  const auto seed = test::test_seed(kSearchSeed);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> classes(3, 9), k(1, 9), recordings(6, 24), phones(3, 12), tlen(1, 30);
  std::normal_distribution<float> opening;
  const std::optional<std::size_t> caps[] = {std::nullopt, 1, 3, 16, 64};
  int searches = 0;
  for (int graph = 0; graph < 20; ++graph) {
    std::vector<VisemeClass> alphabet;
    for (int c = 0, n = classes(rng); c < n; ++c) alphabet.push_back(V(c));
    const auto voice = test::synthetic_voice_graph(static_cast<std::uint32_t>(recordings(rng)), phones(rng), 1 + graph % 3, k(rng),
                                                   rng(), graph % 2 ? 1.0f : 0.05f, alphabet, true, 9);
    std::vector<float> state_jaw(voice.graph->size());
    for (auto& a : state_jaw) a = opening(rng);
    for (int target = 0; target < 5; ++target) {
      std::vector<VisemeClass> targets(static_cast<std::size_t>(tlen(rng)));
      for (auto& v : targets) v = alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
      std::vector<std::int64_t> lengths(targets.size());
      for (auto& n : lengths) n = std::uniform_int_distribution<std::int64_t>(1, 12)(rng);
      std::vector<float> jaw(targets.size());
      for (auto& a : jaw) a = opening(rng);
      bool covered = true;
      for (auto v : targets) covered = covered && !voice.graph->with_viseme(v).empty();
      if (!covered) continue;
      for (auto cap : caps) {
        SearchOptions options{0.1, cap, false, graph % 2 ? 0.3 : 0.0};
        options.jaw_weight = graph % 3 == 0 ? 3.0 : 0.3;
        const SearchTargets shape{lengths, jaw, state_jaw};
        const SearchResult reference = unit_search(*voice.graph, targets, shape, options);
        options.prune_joins = true;
        const SearchResult pruned = unit_search(*voice.graph, targets, shape, options);
        const std::string where = "graph " + std::to_string(graph) + " target " + std::to_string(target) + " cap " +
                                  (cap ? std::to_string(*cap) : "none") + "; " + test::reproduce_hint(seed);
        ASSERT_EQ(pruned.cost, reference.cost) << where;
        ASSERT_EQ(pruned.states, reference.states) << where;
        ASSERT_EQ(pruned.units, reference.units) << where;
        ASSERT_EQ(pruned.stats.active_per_step, reference.stats.active_per_step) << where;
        ++searches;
      }
    }
  }
  EXPECT_GT(searches, 300) << "too few searches to mean anything";
}

// The pruned join evaluation (the default) against the reference that evaluates every pair:
// identical states, units, cost (to the bit) and active counts, on random graphs of random shape
// and spread, with and without caps and hard joins; on every other graph phones and targets have
// random lengths and the duration term is on.
TEST(UnitSearch, PrunedJoinsGiveTheReferenceResultToTheBit) {
  const auto seed = test::test_seed(kSearchSeed);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> classes(3, 9), k(1, 9), recordings(6, 24), phones(3, 12), tlen(1, 30);
  const std::optional<std::size_t> caps[] = {std::nullopt, 1, 3, 16, 64};
  const double betas[] = {0.02, 0.1, 1.0};
  const float noises[] = {0.0f, 0.05f, 1.0f};
  int searches = 0, hard = 0;
  for (int graph = 0; graph < 60; ++graph) {
    std::vector<VisemeClass> alphabet;
    for (int c = 0, n = classes(rng); c < n; ++c) alphabet.push_back(V(c));
    const bool timed = graph % 2 == 1;
    const double weight = timed ? 0.3 : 0.0;
    const auto voice = test::synthetic_voice_graph(static_cast<std::uint32_t>(recordings(rng)), phones(rng), 1 + graph % 3, k(rng),
                                                   rng(), noises[graph % 3], alphabet, true, timed ? 9 : 0);
    for (int target = 0; target < 5; ++target) {
      std::vector<VisemeClass> targets(static_cast<std::size_t>(tlen(rng)));
      for (auto& v : targets) v = alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
      std::vector<std::int64_t> lengths(targets.size());
      for (auto& n : lengths) n = std::uniform_int_distribution<std::int64_t>(1, 12)(rng);
      bool covered = true;
      for (auto v : targets) covered = covered && !voice.graph->with_viseme(v).empty();
      if (!covered) continue;
      for (double beta : betas)
        for (auto cap : caps) {
          const SearchResult reference = unit_search(*voice.graph, targets, lengths, {beta, cap, false, weight});
          const SearchResult pruned = unit_search(*voice.graph, targets, lengths, {beta, cap, true, weight});
          const std::string where = "graph " + std::to_string(graph) + " target " + std::to_string(target) +
                                    " beta " + std::to_string(beta) + " cap " + (cap ? std::to_string(*cap) : "none") +
                                    " duration weight " + std::to_string(weight) +
                                    "; " + test::reproduce_hint(seed);
          ASSERT_EQ(pruned.cost, reference.cost) << where;
          ASSERT_EQ(pruned.states, reference.states) << where;
          ASSERT_EQ(pruned.units, reference.units) << where;
          ASSERT_EQ(pruned.stats.active_per_step, reference.stats.active_per_step) << where;
          ASSERT_EQ(pruned.stats.hard_joins, reference.stats.hard_joins) << where;
          ++searches;
          hard += reference.stats.hard_joins > 0;
        }
    }
  }
  EXPECT_GT(searches, 900) << "too few searches to mean anything";
  EXPECT_GT(hard, 0) << "no search went through a hard join";
}

// The same on graphs large enough that every step has hundreds of entries and a full cap (the
// cap's selection, the sketches and the reading order all at the sizes of a voice), with class
// shapes under light and heavy noise, as the synthesis benchmark has them; under heavy noise with
// the duration term on.
TEST(UnitSearch, PrunedJoinsGiveTheReferenceResultOnLargeSteps) {
  std::mt19937_64 rng(test::test_seed(kSearchSeed));
  int searches = 0;
  for (float noise : {0.1f, 1.0f}) {
    // Under heavy noise the phones have random lengths and the duration term is on.
    const bool timed = noise > 0.5f;
    const auto voice = test::synthetic_voice_graph(200, 30, 3, 6, rng(), noise, Vs({0, 1, 2, 3, 4}), true, timed ? 8 : 0);
    std::vector<VisemeClass> targets(40);
    for (auto& v : targets) v = V(std::uniform_int_distribution<int>(0, 4)(rng));
    std::vector<std::int64_t> lengths(targets.size());
    for (auto& n : lengths) n = std::uniform_int_distribution<std::int64_t>(2, 9)(rng);
    for (const std::optional<std::size_t> cap : {std::optional<std::size_t>{}, std::optional<std::size_t>{16},
                                                 std::optional<std::size_t>{64}}) {
      const double weight = timed ? 0.3 : 0.0;
      const SearchResult reference = unit_search(*voice.graph, targets, lengths, {0.1, cap, false, weight});
      const SearchResult pruned = unit_search(*voice.graph, targets, lengths, {0.1, cap, true, weight});
      const std::string where = "noise " + std::to_string(noise) + " cap " + (cap ? std::to_string(*cap) : "none") +
                                "; " + test::reproduce_hint(test::test_seed(kSearchSeed));
      ASSERT_EQ(pruned.cost, reference.cost) << where;
      ASSERT_EQ(pruned.states, reference.states) << where;
      ASSERT_EQ(pruned.units, reference.units) << where;
      ASSERT_EQ(pruned.stats.active_per_step, reference.stats.active_per_step) << where;
      ++searches;
    }
  }
  EXPECT_EQ(searches, 6);
}

// The bounds the pruning rests on (join_bound.hpp, join_sketch.hpp) never exceed the cost
// they bound: every admissible join of random graphs, at scales from 1e-6 to 1e6 and far from the
// origin.
TEST(JoinBound, NeverExceedsTheJoinCost) {
  std::mt19937_64 rng(test::test_seed(kSearchSeed));
  int pairs = 0, tight = 0;
  for (float scale : {1e-6f, 1.0f, 1e6f})
    for (float offset : {0.0f, 1e3f})
      for (int graph = 0; graph < 4; ++graph) {
        auto voice = test::synthetic_voice_graph(12, 8, 1 + graph % 3, 1 + 4 * graph, rng(), 0.3f, Vs({0, 1, 2, 3}));
        voice.frames = (voice.frames.array() * scale + offset * scale).matrix();
        const PhoneGraph g(voice.states, join_features(voice.states, voice.frames));
        const auto& bound = g.join_bound();
        for (StateId j = 0; j < g.size(); ++j) {
          if (!g.has_parent(j)) continue;
          const VisemeClass from = g.state(j - 1).viseme, to = g.state(j).viseme;
          const DivisemePoints& points = bound.points(g, from, to);
          const auto entries = g.entries(from, to);
          const auto m = static_cast<std::size_t>(std::find(entries.begin(), entries.end(), j) - entries.begin());
          ASSERT_LT(m, entries.size());
          for (StateId i : g.with_viseme(from)) {
            // Computed per call at first, then from the diviseme's table (the same values).
            JoinPoint exit;
            bound.exits(g, from, to, std::span(&i, 1), std::span(&exit, 1));
            const float floor = JoinBound::twice_cost_floor(points.entry[m], exit);
            const float cost = join_cost(g, i, j);
            ASSERT_LE(floor, 2.0f * cost) << "scale " << scale << " offset " << offset << " i " << i << " j " << j;
            // The sketch bound (join_sketch.hpp), from the same tables the search reads.
            ASSERT_TRUE(bound.sketched());
            const DivisemeSketches* entry_sketches = bound.entry_sketches(g, from, to);
            if (!entry_sketches) entry_sketches = bound.entry_sketches(g, from, to);  // made on the second call
            ASSERT_NE(entry_sketches, nullptr);
            SketchRef sketch;
            std::vector<std::int16_t> buffer;
            bound.exit_sketches(g, from, std::span(&i, 1), std::span(&sketch, 1), buffer);
            const auto dims = g.join_features().entry.cols();
            const std::int32_t distance2 =
                sketch_distance2(entry_sketches->entry.data() + m * static_cast<std::size_t>(dims), sketch.values, dims);
            const double sketch_floor = sketch_cost_floor(
                distance2, double{entry_sketches->error[m]} + sketch.error, bound.sketch_grid().step);
            ASSERT_LE(sketch_floor, double{cost}) << "scale " << scale << " offset " << offset << " i " << i << " j " << j;
            tight += sketch_floor > 0.9 * cost;
            ++pairs;
          }
        }
      }
  EXPECT_GT(pairs, 10000);
  EXPECT_GT(tight, pairs / 2) << "the sketch bound is valid but too loose to prune";
}

TEST(UnitSearch, PrefersOneLongUnitOverPieces) {
  std::mt19937_64 rng(1);
  // Recording 1 holds the whole target; recordings 0 and 2 hold only pieces of it.
  const Toy toy = make_toy({{0, 1, 5}, {3, 0, 1, 2, 4}, {2, 4, 3}}, rng);
  const PhoneGraph g(toy.states, join_features(toy.states, toy.frames));
  const std::vector<VisemeClass> targets = Vs({0, 1, 2, 4});
  const SearchResult r = unit_search(g, targets, {0.0, {}});  // fewest units alone
  ASSERT_EQ(r.units.size(), 1u);
  EXPECT_EQ(r.units[0], (Unit{4, 0, 4}));
  EXPECT_EQ(r.cost, 1.0);
}

TEST(UnitSearch, JoinsOnlyWhereTheParentVisemeMatches) {
  std::mt19937_64 rng(2);
  // Target 0 1 2: recording 0 gives "0 1"; "2" exists after a 1 (recording 1) and after a 3
  // (recording 2). Only recording 1's /2/ may follow a unit ending in viseme 1.
  const Toy toy = make_toy({{0, 1}, {1, 2}, {3, 2}}, rng);
  const PhoneGraph g(toy.states, join_features(toy.states, toy.frames));
  const std::vector<VisemeClass> targets = Vs({0, 1, 2});
  const SearchResult r = unit_search(g, targets, {1.0, {}});
  ASSERT_EQ(r.states.size(), 3u);
  EXPECT_EQ(r.states[2], 3u);
  EXPECT_EQ(r.stats.hard_joins, 0u);
}

TEST(UnitSearch, UncoverableVisemeIsNamed) {
  std::mt19937_64 rng(3);
  const Toy toy = make_toy({{0, 1}}, rng);
  const PhoneGraph g(toy.states);
  const std::vector<VisemeClass> targets = Vs({0, 7});  // class 7: sibilant, never recorded
  try {
    unit_search(g, targets, {0.0, {}});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("(target phone 1)"), std::string::npos) << e.what();
  }
}

TEST(UnitSearch, CapBoundsActiveStatesAndStillFindsAPath) {
  std::mt19937_64 rng(4);
  std::uniform_int_distribution<int> visemes(0, 5);
  std::vector<std::vector<int>> utts(200);
  for (auto& u : utts) {
    u.resize(12);
    for (auto& v : u) v = visemes(rng);
  }
  const Toy toy = make_toy(utts, rng);
  const PhoneGraph g(toy.states, join_features(toy.states, toy.frames));
  std::vector<VisemeClass> targets(40);
  for (auto& v : targets) v = V(visemes(rng));
  const SearchResult full = unit_search(g, targets, {0.1, {}});
  const SearchResult capped = unit_search(g, targets, {0.1, 8});
  // The first phone keeps, beside the cap's worth, every state of its class that goes on in the
  // second target's class (they all start at cost 1); the others keep the cap.
  std::size_t going_on = 0;
  for (StateId j : g.with_viseme(targets[0])) going_on += g.child_viseme(j) == targets[1];
  EXPECT_EQ(capped.stats.active_per_step[0],
            going_on + std::min<std::size_t>(8, g.with_viseme(targets[0]).size() - going_on));
  for (std::size_t t = 1; t < capped.stats.active_per_step.size(); ++t) EXPECT_LE(capped.stats.active_per_step[t], 8u);
  EXPECT_GT(*std::max_element(full.stats.active_per_step.begin(), full.stats.active_per_step.end()), 8u);
  EXPECT_GE(capped.cost, full.cost - 1e-9) << "pruning can only lose optimality, never gain it";
  EXPECT_EQ(capped.states.size(), targets.size());
}

// Every state of the first class starts at the same cost; the cap must not choose among them by
// state id. Recordings 0-9 start with class 0 but go on in class 5; only recording 10 spells the
// whole target. Capped at 2, the search still finds it (kept for going on in class 1): one unit.
TEST(UnitSearch, TheCapDoesNotChooseAmongTheFirstPhonesEqualStarts) {
  std::mt19937_64 rng(7);
  std::vector<std::vector<int>> utts(10, std::vector<int>{0, 5});
  utts.push_back({0, 1, 2});
  const Toy toy = make_toy(utts, rng);
  const PhoneGraph g(toy.states, join_features(toy.states, toy.frames));
  const std::vector<VisemeClass> targets = Vs({0, 1, 2});
  const SearchResult r = unit_search(g, targets, {0.1, 2});
  ASSERT_EQ(r.units.size(), 1u);
  EXPECT_EQ(r.units[0], (Unit{20, 0, 3}));
}

// The right-context term: three paths of two units spell 0 1 2 3. Leaving recording 0's /1/
// (recorded before a 4) or recording 1's /2/ (before a 5) leaves a phone recorded in another
// context; leaving recording 1's /1/, recorded before a 2 as the target has it, does not. At
// beta 0 the three cost 2 units each: without the term the tie goes to the lowest state (recording
// 0's /1/), with it to the unit left in its own context.
TEST(UnitSearch, ContextTermLeavesUnitsWhereTheirRecordingGoesOnAsTheTarget) {
  std::mt19937_64 rng(8);
  const Toy toy = make_toy({{0, 1, 4}, {0, 1, 2, 5}, {1, 2, 3}}, rng);  // states 0-2, 3-6, 7-9
  const PhoneGraph g(toy.states, join_features(toy.states, toy.frames));
  const std::vector<VisemeClass> targets = Vs({0, 1, 2, 3});
  SearchOptions paper{0.0, {}};
  paper.context_weight = 0.0;
  SearchOptions context = paper;
  context.context_weight = 0.3;
  const SearchResult without = unit_search(g, targets, paper);
  const SearchResult with = unit_search(g, targets, context);
  EXPECT_EQ(without.states, (std::vector<StateId>{0, 1, 8, 9}));
  EXPECT_EQ(with.states, (std::vector<StateId>{3, 4, 8, 9}));
  EXPECT_EQ(with.cost, 2.0);
  EXPECT_EQ(with.units.size(), 2u);
}

TEST(UnitSearch, ContextWeightMustBeFiniteAndNonNegative) {
  std::mt19937_64 rng(9);
  const Toy toy = make_toy({{0, 1}}, rng);
  const PhoneGraph g(toy.states);
  SearchOptions o;
  for (double w : {-0.1, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    o.context_weight = w;
    EXPECT_THROW(unit_search(g, Vs({0, 1}), o), std::invalid_argument) << w;
  }
}

TEST(UnitSearch, HardJoinWhenADivisemeWasNeverRecorded) {
  std::mt19937_64 rng(5);
  const Toy toy = make_toy({{0, 1}, {2, 3}}, rng);
  const PhoneGraph g(toy.states);
  const std::vector<VisemeClass> targets = Vs({1, 3});  // "1 3" never occurs; no /3/ follows a /1/
  const SearchResult r = unit_search(g, targets, {0.0, {}});  // a graph without join features
  EXPECT_EQ(r.stats.hard_joins, 1u);
  EXPECT_EQ(r.states, (std::vector<StateId>{1, 3}));
}

TEST(PhoneGraph, IndexesStatesByVisemeAndDiviseme) {
  std::mt19937_64 rng(6);
  const Toy toy = make_toy({{0, 1, 0}, {1, 0}}, rng);
  const PhoneGraph g(toy.states);
  EXPECT_EQ(std::vector<StateId>(g.with_viseme(V(0)).begin(), g.with_viseme(V(0)).end()), (std::vector<StateId>{0, 2, 4}));
  EXPECT_EQ(std::vector<StateId>(g.entries(V(1), V(0)).begin(), g.entries(V(1), V(0)).end()), (std::vector<StateId>{2, 4}));
  EXPECT_TRUE(g.entries(V(0), V(0)).empty());
  EXPECT_FALSE(g.has_parent(3));
  EXPECT_TRUE(g.has_parent(4));
  EXPECT_THROW(PhoneGraph({{1, V(0), {0, 1}}, {0, V(0), {1, 1}}}), std::invalid_argument);
  EXPECT_THROW(PhoneGraph({{0, V(21), {0, 1}}}), std::invalid_argument);
}

TEST(PhoneGraph, JoinCostIsTheMeanSquaredSecondDifference) {
  // Two recordings of one phone each, 2 frames each, k = 1: trajectories [0, 1] and [5, 3].
  std::vector<PhoneState> states{{0, V(0), {0, 2}}, {1, V(1), {2, 2}}};
  Eigen::MatrixXf frames(4, 1);
  frames << 0, 1, 5, 3;
  const PhoneGraph g(states, join_features(states, frames));
  // Concatenated 0 1 5 3: second differences at the join are 5-2+0 = 3 and 3-10+1 = -6.
  EXPECT_FLOAT_EQ(join_cost(g, 0, 1), 0.5f * (9 + 36));
}

}  // namespace
}  // namespace fapcast
