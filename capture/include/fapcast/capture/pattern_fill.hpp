#pragma once
// Pattern filling of the gaps a spline cannot bridge (gap_fill.hpp leaves gaps longer than 4
// frames and those at a take's ends). A long gap in a lip marker spans a whole closure or
// release: a straight line between its edges (what the voice build drew before) erases it. A
// marker on the same lip keeps nearly the same offset while the lips move, so the gap follows
// that donor's trajectory, the offset blended linearly from one edge of the gap to the other (held
// at a take's end) - the "pattern fill" of motion-capture editors. Done on head-stabilised frames,
// where the offset between two markers on one lip changes only with the lip's own shape.
#include <Eigen/Core>

#include <cstddef>
#include <span>
#include <vector>

#include "fapcast/corpus/marker_frames.hpp"

namespace fapcast {

struct PatternFillOptions {
  // The donor is chosen on the frames this far either side of the gap (1 s at 60 fps): what the
  // two markers do together near the gap, not in another word.
  Eigen::Index window_frames = 60;
};

struct PatternFilledGap {
  Eigen::Index marker;       // marker row
  Eigen::Index first_frame;  // first missing frame
  Eigen::Index frame_count;
  Eigen::Index donor;        // the marker whose trajectory it follows
};

struct PatternFillResult {
  MarkerFrames<Centimetres> frames;      // the input with the filled gaps
  std::vector<PatternFilledGap> filled;  // in donor_rows then frame order
};

// Fills every gap of every marker of `donor_rows` (the markers that move with the face; in their
// order) that has a donor: another marker of `donor_rows` present
// at every frame of the gap and at its present edges, whose offset to the marker varies least
// (RMS about its mean, over the window's frames where both are present) - and less than the
// marker's own position does, else a straight line serves as well and the gap is left to the
// caller. Gaps without a donor stay missing. A marker with no present frame is left alone.
PatternFillResult pattern_fill(const MarkerFrames<Centimetres>& frames, std::span<const std::size_t> donor_rows,
                               const PatternFillOptions& options = {});

}  // namespace fapcast
