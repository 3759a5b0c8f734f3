#pragma once
// Gap filling of dropped markers: a natural cubic spline through a marker's present samples,
// evaluated in gaps of at most max_gap_frames; longer gaps and gaps at the take's ends are
// reported, never silently filled.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "fapcast/corpus/marker_frames.hpp"

namespace fapcast {

struct GapFillOptions {
  // Longest gap filled: 4 frames = 67 ms at 60 fps. Lips move fast in speech: on the reference
  // talker the lower-lip RMS fill error is 0.23 mm for 1-frame gaps, 1.1 mm for 4 and 4.8 mm
  // for 12 (spec/talker.md), so longer gaps are reported rather than filled.
  Eigen::Index max_gap_frames = 4;
};

enum class GapOutcome {
  filled,
  too_long,      // longer than max_gap_frames: left missing
  at_edge,       // touches the first or last frame: nothing to interpolate between
  too_few_samples,  // the marker has fewer than 2 present samples
};

struct MarkerGap {
  Eigen::Index marker;       // marker row
  Eigen::Index first_frame;  // first missing frame
  Eigen::Index frame_count;  // number of consecutive missing frames
  GapOutcome outcome;
};

struct GapFillResult {
  MarkerFrames<Centimetres> frames;          // filled where outcome == filled
  std::vector<MarkerGap> gaps;  // every gap found, in marker then frame order
  // Gaps left missing.
  std::size_t unfilled_count() const;
};

// Fills short gaps of every marker; see GapFillOptions and GapOutcome.
GapFillResult fill_gaps(const MarkerFrames<Centimetres>& frames, const GapFillOptions& options = {});

// Natural cubic spline through (x[i], y[i]), x strictly increasing, n >= 2, evaluated at xs.
Eigen::VectorXd natural_cubic_spline(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                     const Eigen::VectorXd& xs);

}  // namespace fapcast
