#pragma once
// How well a synthesised trajectory follows a measured one in physical units
// (spec/articulography.md, "Measures"): the ratio of their ranges, their correlation as sampled,
// and the delay that aligns them best. Unlike lip_measures.hpp's CurveAgreement, nothing is
// normalised: a face that moves twice as far as the talker scores a range ratio of 2.
#include <cstddef>
#include <span>
#include <vector>

namespace fapcast {

struct TrajectoryAgreement {
  double reference_range = 0;  // p95 - p5 of the reference (the real talker), its unit
  double compared_range = 0;   // p95 - p5 of the compared curve (the synthesised face)
  double range_ratio = 0;      // compared / reference (0 when the reference is flat)
  double r_zero_lag = 0;       // Pearson r as sampled
  double best_lag_s = 0;       // the delay d maximising r(reference(t), compared(t + d)): > 0 = compared behind
  double r_best_lag = 0;       // r at that delay
};

// Compares `compared` with `reference`, both sampled at `rate_hz` on one grid (same length, >= 3).
// Delays from -max_lag_s to +max_lag_s in steps of step_s: the compared curve is read at t + d by
// linear interpolation and correlated with the reference over the samples where t + d lies on
// it; ties go to the smallest |d|. Throws std::invalid_argument for curves of different or too
// short lengths and for rate <= 0, max lag < 0 or step <= 0.
TrajectoryAgreement trajectory_agreement(std::span<const double> reference, std::span<const double> compared,
                                         double rate_hz, double max_lag_s = 0.2, double step_s = 0.001);

// Samples [begin, end) of a curve.
struct SampleSpan {
  std::size_t begin = 0, end = 0;
};

// Where the zero-lag correlation is lost. With z the z-scores of each curve (population standard
// deviation, over the n samples where both are numbers), 1 - r = sum_t (z_compared(t) -
// z_reference(t))^2 / (2n): a sum of terms >= 0, one per sample. Returns that sum over each span,
// so that spans partitioning the curves add up to 1 - r. A flat curve (r = 0) loses 1/n at every
// sample where both are numbers. Throws std::invalid_argument for curves of different lengths and
// for a span that is reversed or runs past them.
std::vector<double> correlation_loss_by_span(std::span<const double> reference, std::span<const double> compared,
                                             std::span<const SampleSpan> spans);

}  // namespace fapcast
