#include "fapcast/eval/boundary_agreement.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace fapcast {
namespace {

constexpr SampleRate kMillisecondRate{1000};  // one sample a millisecond

std::vector<TimedPhone> phones(std::initializer_list<std::pair<Phone, std::int64_t>> starts, std::int64_t end) {
  std::vector<TimedPhone> out;
  for (const auto& [p, s] : starts) {
    if (!out.empty()) out.back().end_sample = s;
    out.push_back({p, s, end});
  }
  return out;
}

TEST(BoundaryAgreement, IdenticalAlignmentsAgreeExactly) {
  const auto a = phones({{Phone::SIL, 0}, {Phone::HH, 100}, {Phone::AY, 160}, {Phone::SIL, 300}}, 400);
  const BoundaryAgreement r = boundary_agreement(a, a, kMillisecondRate);
  EXPECT_EQ(r.errors_s, (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(r.matched, 4u);
  EXPECT_DOUBLE_EQ(r.within(0.0), 1.0);
}

TEST(BoundaryAgreement, ShiftedBoundariesAreMeasuredInSeconds) {
  const auto ref = phones({{Phone::SIL, 0}, {Phone::HH, 100}, {Phone::AY, 160}, {Phone::SIL, 300}}, 400);
  const auto hyp = phones({{Phone::SIL, 0}, {Phone::HH, 110}, {Phone::AY, 130}, {Phone::SIL, 340}}, 400);
  const BoundaryAgreement r = boundary_agreement(ref, hyp, kMillisecondRate);
  ASSERT_EQ(r.errors_s.size(), 3u);
  EXPECT_DOUBLE_EQ(r.errors_s[0], 0.010);
  EXPECT_DOUBLE_EQ(r.errors_s[1], 0.030);
  EXPECT_DOUBLE_EQ(r.errors_s[2], 0.040);
  EXPECT_NEAR(r.within(0.025), 1.0 / 3, 1e-12);
  EXPECT_NEAR(r.within(0.035), 2.0 / 3, 1e-12);
}

TEST(BoundaryAgreement, IdenticalNeighboursMergeAndAnInsertionOffersTheNearestEdge) {
  // the reference splits a silence in two; the hypothesis inserts a T between HH and AY
  const auto ref = phones({{Phone::SIL, 0}, {Phone::SIL, 50}, {Phone::HH, 100}, {Phone::AY, 160}}, 300);
  const auto hyp = phones({{Phone::SIL, 0}, {Phone::HH, 100}, {Phone::T, 140}, {Phone::AY, 170}}, 300);
  const BoundaryAgreement r = boundary_agreement(ref, hyp, kMillisecondRate);
  EXPECT_EQ(r.reference_phones, 3u);
  ASSERT_EQ(r.errors_s.size(), 2u);
  EXPECT_DOUBLE_EQ(r.errors_s[0], 0.0);
  EXPECT_DOUBLE_EQ(r.errors_s[1], 0.010);  // AY at 160: T's edge at 140 (20 ms) or AY's at 170 (10 ms)
}

TEST(BoundaryAgreement, AWrongPhoneIsCountedAsSubstituted) {
  const auto ref = phones({{Phone::SIL, 0}, {Phone::P, 100}, {Phone::AA, 160}}, 300);
  const auto hyp = phones({{Phone::SIL, 0}, {Phone::B, 100}, {Phone::AA, 160}}, 300);
  const BoundaryAgreement r = boundary_agreement(ref, hyp, kMillisecondRate);
  EXPECT_EQ(r.matched, 2u);
  EXPECT_EQ(r.substituted, 1u);
  EXPECT_EQ(r.deleted, 0u);
}

}  // namespace
}  // namespace fapcast
