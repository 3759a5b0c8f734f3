// The diviseme baseline (System B): every unit is one recorded diviseme, chosen by duration, cut
// at the phone centres and concatenated by concatenate_units.
#include "fapcast/eval/diviseme_baseline.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fapcast {
namespace {

VisemeClass V(int i) { return static_cast<VisemeClass>(i); }

// Recordings given as (viseme, frame count) lists. Frame value = 100 * recording + frame index
// within the recording, so a concatenated frame says which recording it came from.
struct Corpus {
  std::vector<PhoneState> states;
  Eigen::MatrixXf frames;
};

Corpus corpus(const std::vector<std::vector<std::pair<int, std::uint32_t>>>& recordings) {
  Corpus c;
  std::uint32_t f = 0;
  std::vector<float> values;
  for (std::uint32_t u = 0; u < recordings.size(); ++u) {
    std::uint32_t local = 0;
    for (const auto& [v, n] : recordings[u]) {
      c.states.push_back({u, V(v), {f, n}});
      for (std::uint32_t i = 0; i < n; ++i) values.push_back(100.0f * static_cast<float>(u) + static_cast<float>(local++));
      f += n;
    }
  }
  c.frames = Eigen::Map<Eigen::VectorXf>(values.data(), static_cast<Eigen::Index>(values.size()));
  return c;
}

std::vector<TargetPhone> targets(const std::vector<std::pair<int, std::int64_t>>& phones) {
  std::vector<TargetPhone> out;
  std::int64_t f = 0;
  for (const auto& [v, n] : phones) {
    out.push_back({V(v), f, f + n, false});
    f += n;
  }
  return out;
}

TEST(DivisemeBaseline, EveryUnitIsOneRecordedDivisemeOfTheTargetVisemes) {
  const Corpus c = corpus({{{0, 4}, {1, 4}, {2, 4}, {0, 4}},
                           {{0, 6}, {1, 2}, {2, 8}, {3, 4}, {0, 4}},
                           {{0, 4}, {2, 4}, {3, 4}, {0, 4}}});
  const PhoneGraph g(c.states);
  const auto t = targets({{0, 4}, {1, 2}, {2, 8}, {3, 4}, {0, 4}});
  const auto s = select_divisemes(g, t);
  ASSERT_EQ(s.divisemes.size(), t.size() - 1);
  EXPECT_EQ(s.unrecorded, 0u);
  for (std::size_t i = 0; i < s.divisemes.size(); ++i) {
    const auto& d = s.divisemes[i];
    EXPECT_TRUE(d.recorded);
    EXPECT_EQ(d.second_state, d.first_state + 1) << "a diviseme is two consecutive recorded phones";
    EXPECT_EQ(g.state(d.first_state).utterance, g.state(d.second_state).utterance);
    EXPECT_EQ(g.state(d.first_state).viseme, t[i].viseme);
    EXPECT_EQ(g.state(d.second_state).viseme, t[i + 1].viseme);
  }
  // 0-1 was recorded twice: recording 0 with durations 4, 4 (cost log(4/4)^2 + log(4/2)^2 =
  // 0.48 against targets 4, 2) and recording 1 with 6, 2 (log(6/4)^2 = 0.16): recording 1 wins.
  EXPECT_EQ(s.divisemes[0].first_state, 4u) << "the best duration match is recording 1's 0-1";
  EXPECT_EQ(s.divisemes[1].first_state, 5u) << "1-2 with durations 2, 8: recording 1 exactly";
  // 2-3 exists in recordings 1 (8, 4) and 2 (4, 4): targets 8, 4 pick recording 1.
  EXPECT_EQ(s.divisemes[2].first_state, 6u);

  const auto first = select_divisemes(g, t, DivisemeChoiceRule::kFirst);
  EXPECT_EQ(first.divisemes[0].first_state, 0u) << "the first recorded 0-1, whatever its timing";
  EXPECT_EQ(first.divisemes[1].first_state, 1u);
  EXPECT_EQ(first.divisemes[2].first_state, 6u) << "2-3's first recording is recording 1's";
}

TEST(DivisemeBaseline, UnrecordedPairsFallBackAndMissingClassesThrow) {
  const Corpus c = corpus({{{0, 4}, {1, 4}, {0, 4}}, {{0, 4}, {2, 4}, {0, 4}}});
  const PhoneGraph g(c.states);
  const auto s = select_divisemes(g, targets({{0, 4}, {1, 4}, {2, 4}, {0, 4}}));
  EXPECT_EQ(s.unrecorded, 1u) << "1-2 was never recorded";
  EXPECT_FALSE(s.divisemes[1].recorded);
  EXPECT_EQ(g.state(s.divisemes[1].first_state).viseme, V(1));
  EXPECT_EQ(g.state(s.divisemes[1].second_state).viseme, V(2));
  try {
    select_divisemes(g, targets({{0, 4}, {7, 4}, {0, 4}}));
    FAIL() << "class 7 has no state";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("target phone 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(viseme_class_name(V(7))), std::string::npos) << e.what();
  }
  EXPECT_THROW(select_divisemes(g, targets({{0, 4}})), std::invalid_argument);
  EXPECT_THROW(select_divisemes(g, targets({{0, 4}, {1, 0}})), std::invalid_argument);
}

TEST(DivisemeBaseline, OneRecordingWithItsOwnTimingIsReproduced) {
  // Every diviseme of the target exists only in recording 0, with the target's durations, so
  // the halves stitch the recording back together exactly (no blend, no smoothing).
  const Corpus c = corpus({{{0, 4}, {1, 6}, {2, 2}, {3, 8}, {0, 4}}, {{4, 4}, {5, 4}}});
  const PhoneGraph g(c.states);
  const auto t = targets({{0, 4}, {1, 6}, {2, 2}, {3, 8}, {0, 4}});
  const Eigen::MatrixXf y = concatenate_divisemes(g, c.frames, select_divisemes(g, t), t, {0, 0.0, 1.0});
  ASSERT_EQ(y.rows(), 24);
  EXPECT_LT((y - c.frames.topRows(24)).cwiseAbs().maxCoeff(), 1e-4f);
}

TEST(DivisemeBaseline, DivisemesMeetInTheMiddleOfTheSharedPhone) {
  // 0-1 only in recording 0, 1-2 only in recording 1: phone 1's first half must come from
  // recording 0 and its second half from recording 1.
  const Corpus c = corpus({{{0, 4}, {1, 8}, {3, 4}}, {{3, 4}, {1, 8}, {2, 4}}});
  const PhoneGraph g(c.states);
  const auto t = targets({{0, 4}, {1, 8}, {2, 4}});
  const auto s = select_divisemes(g, t);
  const Eigen::MatrixXf y = concatenate_divisemes(g, c.frames, s, t, {0, 0.0, 1.0});
  ASSERT_EQ(y.rows(), 16);
  for (int n = 0; n < 8; ++n) EXPECT_LT(y(n, 0), 100.0f) << "frame " << n << " from recording 0";
  for (int n = 8; n < 16; ++n) EXPECT_GE(y(n, 0), 100.0f) << "frame " << n << " from recording 1";
  EXPECT_NEAR(y(7, 0), 7.0f, 1e-4f) << "the first half runs to the middle of phone 1 in recording 0";
  EXPECT_NEAR(y(8, 0), 108.0f, 1e-4f) << "the second half starts at the middle of phone 1 in recording 1";

  // With the real concatenation options the join is cross-faded and smoothed, not a step of 100.
  const Eigen::MatrixXf smooth = concatenate_divisemes(g, c.frames, s, t);
  EXPECT_LT(std::abs(smooth(8, 0) - smooth(7, 0)), 60.0f);

  // One-frame phones stay whole and still fill every frame.
  const auto short_t = targets({{0, 4}, {1, 1}, {2, 4}});
  EXPECT_EQ(concatenate_divisemes(g, c.frames, select_divisemes(g, short_t), short_t).rows(), 9);
  DivisemeSelection wrong = s;
  wrong.divisemes.pop_back();
  EXPECT_THROW(concatenate_divisemes(g, c.frames, wrong, t), std::invalid_argument);
  wrong = s;
  wrong.divisemes[0].second_state = 4;  // not first_state + 1
  EXPECT_THROW(concatenate_divisemes(g, c.frames, wrong, t), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
