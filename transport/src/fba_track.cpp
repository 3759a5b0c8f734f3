#include "fapcast/transport/fba_track.hpp"

#include "fapcast/core/frame_rate.hpp"

#include <algorithm>

namespace fapcast {
namespace {
__extension__ typedef __int128 Int128;

// The frame whose start is nearest `samples` after the first frame: the sender rounded each
// frame's start to a whole sample, so a difference of two starts may be one sample off the
// exact multiple; rounding to the nearest frame absorbs that.
std::int64_t nearest_frame(std::int64_t samples, FrameRate rate, SampleRate clock_rate) {
  if (samples < 0) return -1;
  const Int128 num = 2 * static_cast<Int128>(samples) * rate.numerator + static_cast<Int128>(clock_rate.hz) * rate.denominator;
  const Int128 den = 2 * static_cast<Int128>(clock_rate.hz) * rate.denominator;
  return static_cast<std::int64_t>(num / den);
}
}  // namespace

std::error_code encode_track_units(const FapSequence& seq, SampleRate clock_rate,
                                   const FbaEncoderOptions& options,
                                   std::vector<MediaUnit>& out, std::int64_t* frame_index) {
  FbaFrameEncoder encoder(options, seq.rate);
  FbaAccessUnit au;
  out.reserve(out.size() + seq.frames.size());
  for (std::size_t k = 0; k < seq.frames.size(); ++k) {
    if (const auto ec = encoder.encode(seq.frames[k], au)) {
      if (frame_index) *frame_index = static_cast<std::int64_t>(k);
      return ec;
    }
    out.push_back({frame_to_sample(static_cast<std::int64_t>(k), seq.rate, clock_rate), std::move(au.bytes), au.intra,
                   options.profile == FbaProfile::kFapcast});
    au = {};
  }
  return {};
}

ReceivedTrack::ReceivedTrack(SampleRate clock_rate, std::int64_t max_frames)
    : clock_rate_{std::max<std::int64_t>(1, clock_rate.hz)}, max_frames_(std::max<std::int64_t>(1, max_frames)) {}

std::error_code ReceivedTrack::add(const ReceivedUnit& unit) {
  const FbaProfile profile = unit.fapcast ? FbaProfile::kFapcast : FbaProfile::kStandard;
  // Prediction across a gap would be wrong; a unit of the other profile starts afresh too.
  if (unit.after_loss || profile != decoder_.profile()) decoder_.reset(profile);
  FapFrame frame;
  if (const auto ec = decoder_.decode(unit.bytes, frame)) {
    ++stats_.decode_errors;
    return ec;
  }
  ++stats_.decoded;
  ++(unit.fapcast ? stats_.fapcast_units : stats_.standard_units);
  if (unit.intra) stats_.fap_quant = decoder_.fap_quant();
  const FrameRate rate = decoder_.rate();
  if (!last_timestamp_) {
    seq_.rate = rate;
    seq_.frames.push_back(frame);
    last_timestamp_ = unit.timestamp;
    last_frame_ = 0;
    return {};
  }
  // Unwrap the 32-bit timestamp: the signed difference to the previous unit.
  const auto step = static_cast<std::int32_t>(unit.timestamp - *last_timestamp_);
  const std::int64_t frame_index = nearest_frame(position_ + step, seq_.rate, clock_rate_);
  if (step <= 0 || frame_index <= last_frame_) {
    ++stats_.out_of_order;
    return {};
  }
  last_timestamp_ = unit.timestamp;
  position_ += step;
  const std::int64_t gap = frame_index - last_frame_ - 1;
  const std::int64_t max_gap = static_cast<std::int64_t>(seq_.rate.fps() * kMaxFilledGapSeconds);
  if (gap > max_gap) {
    ++stats_.discontinuities;
  } else {
    for (std::int64_t i = 0; i < gap && static_cast<std::int64_t>(seq_.frames.size()) < max_frames_; ++i) {
      seq_.frames.push_back(seq_.frames.back());
      ++stats_.held_frames;
    }
  }
  last_frame_ = frame_index;
  if (static_cast<std::int64_t>(seq_.frames.size()) >= max_frames_) {
    ++stats_.over_limit;
    return {};
  }
  seq_.frames.push_back(frame);
  return {};
}

}  // namespace fapcast
