#pragma once
// Two statistics of sampled curves: percentiles (the spread of a curve as p95 - p5, robust to a
// few outlying samples) and Pearson's correlation of two curves.
#include <span>

namespace fapcast {

// The p-th percentile (0..100) of `x` by linear interpolation between order statistics
// (Hyndman & Fan's type 7, the common default), NaN samples skipped. Throws
// std::invalid_argument when no sample is a number or p is outside 0..100.
double percentile(std::span<const double> x, double p);

// Pearson's correlation of two curves of the same length (>= 2 samples), over the samples where
// both are defined (NaN pairs skipped); 0 when either is constant there. Throws
// std::invalid_argument when the lengths differ.
double pearson_correlation(std::span<const double> a, std::span<const double> b);

}  // namespace fapcast
