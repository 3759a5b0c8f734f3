// The retargeting's lip-contact term (voice/lip_contact.hpp): when it acts, how much it adds, and
// the retargeting as an affine image of the map's responses and the amount.
#include "fapcast/voice/lip_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fapcast {
namespace {

// Source vectors of two points (2.2 at rows 0-2, 2.3 at rows 3-5), `gap_mm` apart vertically.
Eigen::VectorXd lips(double gap_mm) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(6);
  x(1) = 0.5 * gap_mm / 1000, x(4) = -0.5 * gap_mm / 1000;
  return x;
}

// A term on a one-response map whose target gap is 6 mm x phi + offset.
LipContact term(double offset_mm) {
  LipContact c;
  c.shape = Eigen::VectorXd::Zero(6);
  c.shape(1) = -0.004, c.shape(4) = 0.004;  // one unit closes the target's lips by 8 mm
  c.gap_weights = Eigen::VectorXd::Constant(1, 0.006);
  c.gap_offset_m = offset_mm / 1000;
  c.shape_gap_m = -0.008;
  c.source_contact_m = 0.0005, c.target_contact_m = 0.0001, c.reach_m = 0.002;
  c.source_upper = 0, c.source_lower = 3;
  return c;
}

TEST(LipContact, ClosesTheTargetAsFarAsTheSourceIsClosed) {
  const LipContact c = term(0.0);
  const Eigen::VectorXd phi = Eigen::VectorXd::Constant(1, 1.0);  // target 6 mm apart
  EXPECT_NEAR(c.source_gap_m(lips(0.5)), 0.0005, 1e-12);
  // Source at contact: the target's whole excess over its contact, 5.9 mm, is closed.
  EXPECT_NEAR(c.amount(lips(0.5), phi), 0.0059 / 0.008, 1e-12);
  // Source 0.8 mm above contact (under half the reach): the target may stay 0.8 mm above its own.
  EXPECT_NEAR(c.amount(lips(1.3), phi), (0.006 - 0.0001 - 0.0008) / 0.008, 1e-12);
  // Over the second half of the reach the amount fades to nothing, and never grows as the source opens.
  double previous = c.amount(lips(1.5), phi);
  for (double gap = 1.6; gap < 2.6; gap += 0.1) {
    const double a = c.amount(lips(gap), phi);
    EXPECT_LE(a, previous + 1e-12) << gap;
    previous = a;
  }
  EXPECT_EQ(c.amount(lips(2.5), phi), 0.0);  // at the reach
  EXPECT_EQ(c.amount(lips(9.0), phi), 0.0);  // an open mouth is the map's alone
}

TEST(LipContact, LeavesClosedTargetsAloneAndCapsTheAmount) {
  const LipContact c = term(0.0);
  EXPECT_EQ(c.amount(lips(0.5), Eigen::VectorXd::Constant(1, 0.0)), 0.0);  // target already 0 mm apart
  EXPECT_EQ(c.amount(lips(0.5), Eigen::VectorXd::Constant(1, 10.0)), LipContact::kMaxAmount);  // 60 mm: capped
  LipContact opens = term(0.0);
  opens.shape_gap_m = 0.001;  // a shape that parts the lips is never added
  EXPECT_EQ(opens.amount(lips(0.5), Eigen::VectorXd::Constant(1, 1.0)), 0.0);
}

TEST(LipContact, RetargetingAddsTheShapeAsOneMoreResponse) {
  const RbfMap map(Eigen::MatrixXd::Zero(2, 6), 1.0, Eigen::MatrixXd::Zero(2, 6), Eigen::VectorXd::Zero(6), 0.0);
  LipContact c = term(6.0);
  c.gap_weights = Eigen::VectorXd::Zero(2);  // the target's lips 6 mm apart whatever the source
  const Retargeting plain(map), whole(map, c);
  EXPECT_EQ(plain.response_count(), 2);
  EXPECT_EQ(whole.response_count(), 3);
  const Eigen::VectorXd r = whole.responses(lips(0.5));
  EXPECT_NEAR(r(2), 0.0059 / 0.008, 1e-12);
  const Eigen::VectorXd y = whole(lips(0.5));
  EXPECT_NEAR(y(1) - y(4), -0.008 * r(2), 1e-12);  // the map adds nothing, the shape closes
  Eigen::MatrixXf out(6, 2);
  Eigen::MatrixXd sources(6, 2);
  sources << lips(0.5), lips(9.0);
  whole.map_columns(sources, out);
  EXPECT_NEAR(out(1, 0), y(1), 1e-7);
  EXPECT_EQ(out(1, 1), 0.0f);  // the open source: no term
  c.gap_weights = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(Retargeting(map, c), std::invalid_argument);  // weights for another map
}

}  // namespace
}  // namespace fapcast
