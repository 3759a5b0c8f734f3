#pragma once
// Zero-phase low-pass filtering of a uniformly sampled curve: a 2nd-order Butterworth section run
// forwards and backwards (magnitude |H|^2, no delay), the ends padded by odd reflection so that
// a ramp passes through nearly unchanged. Used to take coil jitter out of articulography.
#include <span>
#include <vector>

namespace fapcast {

// `x` sampled at `rate_hz` (> 0), cut-off `cutoff_hz` in (0, rate_hz / 2): -6 dB at the cut-off
// (-3 dB each pass). Returns a curve of the same length; fewer than 3 samples are returned as is.
// Throws std::invalid_argument for a rate or cut-off out of range.
std::vector<double> zero_phase_lowpass(std::span<const double> x, double rate_hz, double cutoff_hz);

}  // namespace fapcast
