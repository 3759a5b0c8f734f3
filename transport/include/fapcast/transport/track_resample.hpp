#pragma once
// Resampling a FAP track to another frame rate without drift: output frame j is shown at the
// exact rational time j / to_fps, and source positions are computed from j alone (integers,
// never an accumulated float step), so frame j of an hour-long track is as exact as frame 1.
#include "fapcast/codec/fap_frame.hpp"

#include <cstdint>

namespace fapcast {

enum class ResampleMode {
  // Output frame j shows source frame k = floor(j * from_fps / to_fps): the frame on screen at
  // that instant (what a player holding each frame until the next would show).
  kHold,
  // Low-level FAPs (3..68) masked in both neighbours k and k+1 are interpolated linearly at the
  // exact fraction and rounded half away from zero; the rest (FAP 1 viseme, FAP 2 expression,
  // FAPs masked in only one neighbour) are held from frame k, as are all values of the last frame.
  kLinear,
};

// The source position of output frame j: whole frame `index` plus `remainder / denominator`.
struct SourcePosition {
  std::int64_t index = 0;
  std::int64_t remainder = 0;    // 0 <= remainder < denominator
  std::int64_t denominator = 1;  // to.numerator * from.denominator
};
SourcePosition source_position(std::int64_t j, FrameRate from, FrameRate to);

// Number of output frames covering the source's duration N / from_fps: ceil(N * to / from).
std::int64_t resampled_frame_count(std::int64_t n, FrameRate from, FrameRate to);

// The track at rate `to`. Preconditions: both rates valid. An empty track stays empty.
FapSequence resample_track(const FapSequence& seq, FrameRate to,
                                  ResampleMode mode);

}  // namespace fapcast
