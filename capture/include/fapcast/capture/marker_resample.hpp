#pragma once
// Putting a capture's marker frames on another frame grid (a 120 or 100 fps take onto the voice
// build's 60 fps): output frame k is the take at time k / rate_hz (time 0 = the take's first
// frame), linearly interpolated between the two input frames around it. When that time falls on
// an input frame (120 -> 60: every second frame) the sample is copied bit for bit. An output
// sample is missing when an input sample it is interpolated from is missing. No anti-alias
// filter is applied (spec/voice.md "Corpus" says why this is acceptable for >= 50 fps takes).
#include "fapcast/corpus/marker_frames.hpp"

#include <cstdint>

namespace fapcast {

// `markers` on a grid of `rate_hz` frames per second (1 to 100000), covering the input's time
// span [0, (F - 1) / input rate]: floor((F - 1) x rate_hz / input rate) + 1 frames (0 for an
// empty input). Labels carry; first_frame becomes 1. For a whole-number input rate the source
// position k x input / rate_hz is computed in integers, so it is exact; otherwise in doubles,
// a position within 1e-9 frames of an input frame taken as that frame (and counted as inside).
// Throws std::invalid_argument for a rate out of range, a non-positive or non-finite input rate,
// or an inconsistent set.
MarkerFrames<Millimetres> resample_markers(const MarkerFrames<Millimetres>& markers, std::int32_t rate_hz);

}  // namespace fapcast
