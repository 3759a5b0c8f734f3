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
#include <memory>
#include <optional>
#include <system_error>
#include <vector>

namespace fapcast {

// Encodes every frame of `seq` as one access unit at sample frame_to_sample(k, seq.rate,
// clock_rate). Returns the encoder's error for the first frame it refuses (and `frame_index`).
std::error_code encode_track_units(const FapSequence& seq, SampleRate clock_rate,
                                   const FbaEncoderOptions& options,
                                   std::vector<MediaUnit>& out, std::int64_t* frame_index = nullptr);

// The decode check of RTP source validation for FBA: a run must start with an intra unit and
// every unit must decode, in order, with one decoder (RtpStreamReceiver's probation).
class FbaUnitValidator final : public UnitValidator {
 public:
  bool decodes(const ReceivedUnit& unit) override;
  void restart() override { decoder_.reset(); }

 private:
  FbaFrameDecoder decoder_;
  FapFrame frame_;
};

// ReceiverOptions::make_validator for FBA streams.
std::unique_ptr<UnitValidator> make_fba_unit_validator();

struct ReceivedTrackStats {
  std::uint64_t decoded = 0;          // units decoded into frames
  std::uint64_t decode_errors = 0;    // units the decoder refused (the decoder then needs intra)
  std::uint64_t leading_frames = 0;   // frames before the first decoded one, holding it (a lost start)
  std::uint64_t held_frames = 0;      // frames in gaps, holding the frame before (loss, skips)
  std::uint64_t trailing_frames = 0;  // frames after the last decoded one up to the sender's count
  std::uint64_t timestamp_jumps = 0;  // units whose timestamp is not a frame after the last one
                                      // (backwards, or more than kMaxFilledGapSeconds ahead) and
                                      // that the next unit did not confirm: discarded
  std::uint64_t discontinuities = 0;  // confirmed jumps: the frames continue after the last one
  std::uint64_t over_limit = 0;       // decoded units dropped because the track is full
  std::uint64_t frame_number_mismatches = 0;  // intra units whose frame_number disagrees with
                                              // their timestamp (the timestamp wins)
  std::int64_t first_sender_frame = 0;  // the sender's index of output frame 0
  std::uint64_t report_mismatches = 0;  // a sender report no frame index fits: the lost start not placed
  std::uint64_t standard_units = 0;   // decoded units of the standard syntax ...
  std::uint64_t fapcast_units = 0;    // ... and of the fapcast profile (the payload header's F bit)
  int fap_quant = -1;                 // of the last intra unit decoded (-1: none)
};

// Rebuilds a track from units in sequence order, on the sender's timeline: the first decoded
// (intra) unit's frame_number (fapcast profile, spec/fba.md §9), or for a standard stream a sender
// report made during it (finish()), says which sender frame it is, so output frame k is sender
// frame k even when the first frames were lost (the frames before it hold it); a later unit
// lands at the frame whose start is nearest its timestamp's offset from that anchor, never where
// its arrival order would put it; frames in between hold the previous frame. Memory is bounded by
// the frames of `max_seconds` at the stream's stated frame rate, whatever the timestamps say.
class ReceivedTrack {
 public:
  // Gaps, lost starts and lost ends longer than this many seconds are not filled (a late joiner,
  // a sender restart, a hostile timestamp).
  static constexpr std::int64_t kMaxFilledGapSeconds = 10;

  ReceivedTrack(SampleRate clock_rate, double max_seconds);

  // Decodes one unit and places its frame. Errors come from the FBA decoder.
  std::error_code add(const ReceivedUnit& unit);
  // End of stream: a sender that sent `sender_packets` packets (its final RTCP sender report;
  // one frame per packet) sent that many frames, so lost last frames are held up to its count.
  // `during`: a sender report made during the stream (RtpStreamReceiver::anchor_sender_report),
  // which places a standard stream's first decoded frame on the sender's timeline.
  void finish(std::optional<std::uint32_t> sender_packets,
              const std::optional<SenderReport>& during = std::nullopt);

  // The track has the frames of max_seconds: further units are dropped.
  bool full() const;
  const FapSequence& sequence() const { return seq_; }
  const ReceivedTrackStats& stats() const { return stats_; }
  // Frames of max_seconds at the stream's rate (0 before the first decoded unit).
  std::int64_t max_frames() const { return max_frames_; }

 private:
  struct Pending {
    std::uint32_t timestamp;
    FapFrame frame;
  };
  std::int64_t frames_in(std::int64_t samples) const;  // nearest frame count, -1 when negative
  std::int64_t max_gap() const;
  // The sender's index of the first decoded frame by a report made during the stream.
  std::optional<std::int64_t> sender_frame_of_first(const SenderReport& during) const;
  void append(const FapFrame& frame, std::int64_t index);  // holds the gap before `index`

  SampleRate clock_rate_;
  double max_seconds_;
  std::int64_t max_frames_ = 0;
  FbaFrameDecoder decoder_;
  FapSequence seq_;
  ReceivedTrackStats stats_;
  bool anchored_ = false;
  std::uint32_t last_timestamp_ = 0;
  std::int64_t position_ = 0;      // samples from the anchor unit to the last placed one
  std::int64_t anchor_index_ = 0;  // output index of the anchor unit
  std::int64_t last_index_ = -1;   // output index of the last placed frame
  std::optional<Pending> jump_;    // a unit that jumped, waiting for the next one to confirm it
  std::uint32_t first_timestamp_ = 0;  // of the first decoded unit
  bool numbered_ = false;              // its frame_number placed it (fapcast profile)
};

}  // namespace fapcast
