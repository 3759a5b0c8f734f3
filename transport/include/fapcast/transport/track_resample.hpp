#pragma once
// Resampling a FAP track to another frame rate without drift: output frame j is shown at the
// exact rational time j / to_fps, and source positions are computed from j alone (integers,
// never an accumulated float step), so frame j of an hour-long track is as exact as frame 1.
#include "fapcast/codec/fap_frame.hpp"

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>

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

// resample_track frame by frame, for a track too long to hold: source frames are pushed in
// order, and `sink` gets each output frame (its index j and the frame) as soon as the source
// frames it reads are in; finish() gives the rest. The frames are those resample_track gives for
// all the frames pushed, to the bit; it keeps only the source frames still to be read (two).
class TrackResampler {
 public:
  using Sink = std::function<void(std::int64_t j, const FapFrame& frame)>;
  TrackResampler(FrameRate from, FrameRate to, ResampleMode mode, Sink sink);
  ~TrackResampler();
  TrackResampler(const TrackResampler&) = delete;
  TrackResampler& operator=(const TrackResampler&) = delete;
  void push(const FapFrame& frame);  // std::logic_error after finish()
  void finish();
  std::int64_t frames_out() const { return next_; }

 private:
  struct Common;
  void emit(std::int64_t n);
  FrameRate from_, to_;
  ResampleMode mode_;
  Sink sink_;
  std::unique_ptr<Common> common_;
  std::deque<FapFrame> window_;  // source frames first_, first_ + 1, ...
  std::int64_t first_ = 0;
  std::int64_t pushed_ = 0;
  std::int64_t next_ = 0;  // the next output frame
  bool finished_ = false;
};

}  // namespace fapcast
