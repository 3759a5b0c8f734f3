#pragma once
// Between the two marker layouts: MarkerFrames (the talker's and preprocessing's working form:
// 3M x F, cm, NaN = missing) and MarkerSet (the capture files' form: F x 3M, mm, a mask).
#include "fapcast/corpus/marker_frames.hpp"
#include "fapcast/corpus/marker_set.hpp"

namespace fapcast {

// cm -> mm; NaN samples become missing (0 0 0 with the mask set). Frame rate and labels carry.
MarkerSet to_marker_set(const MarkerFrames& frames);

// mm -> cm; missing samples become NaN. Throws std::invalid_argument when the set's frame rate is
// not a whole number of frames per second (MarkerFrames keeps an integer rate).
MarkerFrames to_marker_frames(const MarkerSet& set);

}  // namespace fapcast
