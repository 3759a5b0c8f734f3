#pragma once
// The bridge between FAP tracks and RTP media units: a track becomes one FBA access unit per
// frame placed on the WAV timeline (sender), and received units become a track again
// (receiver), frames placed by their RTP timestamps so that loss leaves holes, not a shift.
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/fba/fba_stream.hpp"
#include "fapcast/transport/media_unit.hpp"
#include "fapcast/transport/rtp_stream_receiver.hpp"

#include <cstdint>
#include <optional>
#include <system_error>
#include <vector>

namespace fapcast {

// Encodes every frame of `seq` as one access unit at sample frame_to_sample(k, seq.rate,
// clock_rate). Returns the encoder's error for the first frame it refuses (and `frame_index`).
std::error_code encode_track_units(const FapSequence& seq, SampleRate clock_rate,
                                   const FbaEncoderOptions& options,
                                   std::vector<MediaUnit>& out, std::int64_t* frame_index = nullptr);

struct ReceivedTrackStats {
  std::uint64_t decoded = 0;         // units decoded into frames
  std::uint64_t decode_errors = 0;   // units the decoder refused (the decoder then needs intra)
  std::uint64_t held_frames = 0;     // frames filled by holding the previous one (loss, skips)
  std::uint64_t out_of_order = 0;    // units whose timestamp does not advance (dropped)
  std::uint64_t discontinuities = 0; // timestamp jumps too large to fill (frames appended as is)
  std::uint64_t over_limit = 0;      // units dropped because the track reached max_frames
  std::uint64_t standard_units = 0;  // decoded units of the standard syntax ...
  std::uint64_t fapcast_units = 0;   // ... and of the fapcast profile (the payload header's F bit)
  int fap_quant = -1;                // of the last intra unit decoded (-1: none)
};

// Rebuilds a track from units in sequence order. The first decoded frame is frame 0; a later
// unit at timestamp t lands at the frame whose start is nearest t - t0, and frames in
// between hold the previous frame. Memory is bounded by `max_frames` whatever the timestamps say.
class ReceivedTrack {
 public:
  // Gaps longer than this many seconds are not filled (a sender restart, a hostile timestamp).
  static constexpr std::int64_t kMaxFilledGapSeconds = 10;

  ReceivedTrack(SampleRate clock_rate, std::int64_t max_frames);

  // Decodes one unit and places its frame. Errors come from the FBA decoder.
  std::error_code add(const ReceivedUnit& unit);

  const FapSequence& sequence() const { return seq_; }
  const ReceivedTrackStats& stats() const { return stats_; }

 private:
  SampleRate clock_rate_;
  std::int64_t max_frames_;
  FbaFrameDecoder decoder_;
  FapSequence seq_;
  ReceivedTrackStats stats_;
  std::optional<std::uint32_t> last_timestamp_;
  std::int64_t position_ = 0;  // samples since the first decoded frame's timestamp
  std::int64_t last_frame_ = -1;
};

}  // namespace fapcast
