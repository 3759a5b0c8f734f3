// The dominance baseline: viseme targets from the corpus, blended by dominance functions.
#include "fapcast/eval/dominance_baseline.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

std::vector<TargetPhone> targets(const std::vector<std::pair<VisemeClass, std::int64_t>>& phones) {
  std::vector<TargetPhone> out;
  std::int64_t f = 0;
  for (const auto& [v, n] : phones) {
    out.push_back({v, f, f + n, false});
    f += n;
  }
  return out;
}

// Three recordings: sil AA sil, sil P AA sil, sil UW sil; k = 2; each phone's frames hold a
// constant except the centre frame, which holds its class's value, so the targets must come from
// the centre frames.
struct CentreCorpus {
  std::vector<PhoneState> states;
  Eigen::MatrixXf frames;
};

CentreCorpus centre_corpus() {
  CentreCorpus c;
  const std::vector<std::vector<VisemeClass>> recordings{
      {VisemeClass::kSilence, VisemeClass::kOpenUnrounded, VisemeClass::kSilence},
      {VisemeClass::kSilence, VisemeClass::kBilabial, VisemeClass::kOpenUnrounded, VisemeClass::kSilence},
      {VisemeClass::kSilence, VisemeClass::kCloseRounded, VisemeClass::kSilence}};
  std::vector<Eigen::RowVector2f> rows;
  std::uint32_t f = 0;
  for (std::uint32_t u = 0; u < recordings.size(); ++u)
    for (const auto v : recordings[u]) {
      c.states.push_back({u, v, {f, 5}});
      for (int i = 0; i < 5; ++i) {
        const float value = static_cast<float>(v);
        rows.push_back(i == 2 ? Eigen::RowVector2f(value, -value) : Eigen::RowVector2f(99.0f, 99.0f));
      }
      f += 5;
    }
  c.frames.resize(static_cast<Eigen::Index>(rows.size()), 2);
  for (std::size_t i = 0; i < rows.size(); ++i) c.frames.row(static_cast<Eigen::Index>(i)) = rows[i];
  return c;
}

TEST(DominanceBaseline, TargetsAreTheMeanCentreFramesOfEachClass) {
  const CentreCorpus c = centre_corpus();
  const auto t = viseme_targets(PhoneGraph(c.states), c.frames);
  ASSERT_EQ(t.coefficients.rows(), static_cast<Eigen::Index>(kVisemeClassCount));
  EXPECT_EQ(t.phones[static_cast<std::size_t>(VisemeClass::kSilence)], 6u);
  EXPECT_EQ(t.phones[static_cast<std::size_t>(VisemeClass::kOpenUnrounded)], 2u);
  EXPECT_EQ(t.phones[static_cast<std::size_t>(VisemeClass::kDental)], 0u);
  const auto uw = static_cast<Eigen::Index>(VisemeClass::kCloseRounded);
  EXPECT_FLOAT_EQ(t.coefficients(uw, 0), static_cast<float>(uw));
  EXPECT_FLOAT_EQ(t.coefficients(uw, 1), -static_cast<float>(uw));
}

TEST(DominanceBaseline, ALongPhoneReachesItsTarget) {
  const CentreCorpus c = centre_corpus();
  const auto vt = viseme_targets(PhoneGraph(c.states), c.frames);
  const auto phones = targets({{VisemeClass::kSilence, 30}, {VisemeClass::kCloseRounded, 60}, {VisemeClass::kSilence, 30}});
  const Eigen::MatrixXf y = dominance_interpolation(vt, phones);
  ASSERT_EQ(y.rows(), 120);
  const Eigen::RowVectorXf uw = vt.coefficients.row(static_cast<Eigen::Index>(VisemeClass::kCloseRounded));
  EXPECT_LT((y.row(60) - uw).norm(), 0.01f * uw.norm()) << "the middle of a 1 s phone is its target";
  EXPECT_GT((y.row(5) - uw).norm(), 0.5f * uw.norm()) << "the silence before is not";
  for (Eigen::Index n = 1; n < y.rows(); ++n)
    EXPECT_LT((y.row(n) - y.row(n - 1)).norm(), 0.2f * uw.norm()) << "no jumps, frame " << n;
}

// A phone's frames are shown at or after its start; their mean time is where its target peaks, not
// the middle of their span half a frame later (which made the baseline trail its talker by 8 ms).
TEST(DominanceBaseline, APhoneIsCentredOnTheMeanTimeOfItsFrames) {
  const CentreCorpus c = centre_corpus();
  const auto vt = viseme_targets(PhoneGraph(c.states), c.frames);
  const auto phones = targets({{VisemeClass::kSilence, 30}, {VisemeClass::kCloseRounded, 7}, {VisemeClass::kSilence, 30}});
  const Eigen::MatrixXf y = dominance_interpolation(vt, phones);
  const Eigen::RowVectorXf uw = vt.coefficients.row(static_cast<Eigen::Index>(VisemeClass::kCloseRounded));
  const Eigen::Index middle = 33;  // frames 30..36
  for (Eigen::Index j = 1; j <= 3; ++j)
    EXPECT_LT((y.row(middle - j) - y.row(middle + j)).norm(), 1e-4f * uw.norm()) << "symmetric about frame 33, j " << j;
  for (Eigen::Index n = 30; n <= 36; ++n)
    EXPECT_LE((y.row(middle) - uw).norm(), (y.row(n) - uw).norm() + 1e-6f) << "nearest its target at the middle, not " << n;
}

TEST(DominanceBaseline, ContactClassesWinShortPhones) {
  const CentreCorpus c = centre_corpus();
  const auto vt = viseme_targets(PhoneGraph(c.states), c.frames);
  // A 4-frame /p/ between two open vowels: the vowels' dominance cannot pull it open.
  const auto phones = targets({{VisemeClass::kOpenUnrounded, 12}, {VisemeClass::kBilabial, 4},
                               {VisemeClass::kOpenUnrounded, 12}});
  const Eigen::MatrixXf y = dominance_interpolation(vt, phones);
  const Eigen::RowVectorXf p = vt.coefficients.row(static_cast<Eigen::Index>(VisemeClass::kBilabial));
  const Eigen::RowVectorXf a = vt.coefficients.row(static_cast<Eigen::Index>(VisemeClass::kOpenUnrounded));
  const float at_p = (y.row(14) - p).norm();
  EXPECT_LT(at_p, 0.15f * (a - p).norm()) << "the /p/ gets within 15 % of its target";

  // With the contact dominance no larger than a vowel's, the same /p/ is pulled well open.
  DominanceBaselineOptions weak;
  weak.contact = weak.phone;
  EXPECT_GT((dominance_interpolation(vt, phones, weak).row(14) - p).norm(), 2.0f * at_p);
}

TEST(DominanceBaseline, RefusesWhatItCannotSay) {
  const CentreCorpus c = centre_corpus();
  const auto vt = viseme_targets(PhoneGraph(c.states), c.frames);
  try {
    (void)dominance_interpolation(vt, targets({{VisemeClass::kSilence, 5}, {VisemeClass::kDental, 5}}));
    FAIL() << "no dental phone was recorded";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(viseme_class_name(VisemeClass::kDental)), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)dominance_interpolation(vt, targets({{VisemeClass::kSilence, 0}})), std::invalid_argument);
  std::vector<TargetPhone> overlapping{{VisemeClass::kSilence, 0, 5, false}, {VisemeClass::kSilence, 3, 8, false}};
  EXPECT_THROW((void)dominance_interpolation(vt, overlapping), std::invalid_argument);
  EXPECT_EQ(dominance_interpolation(vt, std::vector<TargetPhone>{}).rows(), 0);
}

}  // namespace
}  // namespace fapcast
