#include "fapcast/transport/fba_track.hpp"

#include "fapcast/core/frame_rate.hpp"

#include <algorithm>
#include <cmath>

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

bool FbaUnitValidator::decodes(const ReceivedUnit& unit) {
  const FbaProfile profile = unit.fapcast ? FbaProfile::kFapcast : FbaProfile::kStandard;
  if (profile != decoder_.profile()) decoder_.reset(profile);
  if (unit.bytes.empty() || (decoder_.needs_intra() && !unit.intra)) return false;
  if (decoder_.decode(unit.bytes, frame_)) {
    decoder_.reset();
    return false;
  }
  return true;
}

std::unique_ptr<UnitValidator> make_fba_unit_validator() {
  return std::make_unique<FbaUnitValidator>();
}

ReceivedTrack::ReceivedTrack(SampleRate clock_rate, double max_seconds)
    : clock_rate_{std::max<std::int64_t>(1, clock_rate.hz)}, max_seconds_(std::max(0.0, max_seconds)) {}

std::int64_t ReceivedTrack::frames_in(std::int64_t samples) const {
  return nearest_frame(samples, seq_.rate, clock_rate_);
}

std::int64_t ReceivedTrack::max_gap() const {
  return static_cast<std::int64_t>(seq_.rate.fps() * kMaxFilledGapSeconds);
}

bool ReceivedTrack::full() const {
  return anchored_ && static_cast<std::int64_t>(seq_.frames.size()) >= max_frames_;
}

void ReceivedTrack::append(const FapFrame& frame, std::int64_t index) {
  for (std::int64_t i = last_index_ + 1; i < index && !full(); ++i) {
    seq_.frames.push_back(seq_.frames.back());
    ++stats_.held_frames;
  }
  last_index_ = index;
  if (full()) {
    ++stats_.over_limit;
    return;
  }
  seq_.frames.push_back(frame);
}

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
  if (!anchored_) {
    // The first decoded unit is an intra one (the decoder refuses P units before it), and its
    // frame_number is the sender's index of this frame: the frames before it were lost.
    seq_.rate = decoder_.rate();
    max_frames_ = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(std::floor(max_seconds_ * seq_.rate.fps() + 1e-9)));
    const std::int64_t number = std::max(0, decoder_.last_frame_number());
    const std::int64_t lead = number <= max_gap() ? number : 0;  // a late joiner starts at its join
    stats_.first_sender_frame = number - lead;
    anchored_ = true;
    first_timestamp_ = unit.timestamp;
    numbered_ = decoder_.last_frame_number() >= 0;
    last_timestamp_ = unit.timestamp;
    position_ = 0;
    anchor_index_ = lead;
    for (std::int64_t i = 0; i < lead && !full(); ++i) {
      seq_.frames.push_back(frame);
      ++stats_.leading_frames;
    }
    last_index_ = lead - 1;
    append(frame, lead);
    return {};
  }
  if (full()) {
    ++stats_.over_limit;
    return {};
  }
  // Unwrap the 32-bit timestamp: the signed difference to the last placed unit.
  const auto step = static_cast<std::int32_t>(unit.timestamp - last_timestamp_);
  const std::int64_t index = anchor_index_ + frames_in(position_ + step);
  if (step > 0 && index > last_index_ && index - last_index_ - 1 <= max_gap()) {
    if (jump_) {  // the unit before jumped and this one did not follow it
      ++stats_.timestamp_jumps;
      jump_.reset();
    }
    if (unit.intra && decoder_.last_frame_number() >= 0 &&
        ((stats_.first_sender_frame + index) & 0xffff) != decoder_.last_frame_number())
      ++stats_.frame_number_mismatches;
    last_timestamp_ = unit.timestamp;
    position_ += step;
    append(frame, index);
    return {};
  }
  if (jump_) {
    const auto from_jump = static_cast<std::int32_t>(unit.timestamp - jump_->timestamp);
    const std::int64_t after = frames_in(from_jump);
    if (from_jump > 0 && after >= 1 && after - 1 <= max_gap()) {
      // Two units agree: the sender's timeline jumped. Its frames go on after the last one.
      ++stats_.discontinuities;
      anchor_index_ = last_index_ + 1;
      last_timestamp_ = jump_->timestamp;
      position_ = 0;
      append(jump_->frame, anchor_index_);
      jump_.reset();
      last_timestamp_ = unit.timestamp;
      position_ = from_jump;
      append(frame, anchor_index_ + after);
      return {};
    }
    ++stats_.timestamp_jumps;
  }
  jump_ = Pending{unit.timestamp, frame};
  return {};
}

std::optional<std::int64_t> ReceivedTrack::sender_frame_of_first(const SenderReport& during) const {
  // The report was sent at instant s_r with packet_count = c: the sender's frames 0..c-1 started
  // before s_r, frame c at or after it (one frame per packet, no skipped frames). The first
  // decoded unit lies d = its timestamp - the report's samples from it: its frame k is the one
  // whose start minus d falls in (start of c - 1, start of c].
  const std::int64_t c = during.packet_count;
  const std::int64_t d = static_cast<std::int32_t>(first_timestamp_ - during.rtp_timestamp);
  const auto fits = [&](std::int64_t k) {
    if (k < 0) return false;
    const std::int64_t at = frame_to_sample(k, seq_.rate, clock_rate_) - d;
    return at <= frame_to_sample(c, seq_.rate, clock_rate_) &&
           (c == 0 || at > frame_to_sample(c - 1, seq_.rate, clock_rate_));
  };
  const std::int64_t estimate = c + static_cast<std::int64_t>(std::floor(
      static_cast<double>(d) * seq_.rate.fps() / static_cast<double>(clock_rate_.hz)));
  for (const std::int64_t k : {estimate, estimate + 1, estimate - 1, estimate + 2})
    if (fits(k)) return k;
  return std::nullopt;
}

void ReceivedTrack::finish(std::optional<std::uint32_t> sender_packets,
                           const std::optional<SenderReport>& during) {
  if (jump_) {
    ++stats_.timestamp_jumps;
    jump_.reset();
  }
  // A standard unit carries no frame_number: a sender report made during the stream says which
  // sender frame the first decoded one is, so that a lost start is held, not cut (audio sync).
  if (anchored_ && during && !numbered_ && stats_.first_sender_frame == 0 && stats_.discontinuities == 0) {
    const std::optional<std::int64_t> k = sender_frame_of_first(*during);
    const std::int64_t first_index = anchor_index_;  // no discontinuity: still the first unit's
    if (!k) {
      ++stats_.report_mismatches;
    } else if (*k > first_index && *k - first_index <= max_gap()) {
      const std::int64_t lead = *k - first_index;
      seq_.frames.insert(seq_.frames.begin(), static_cast<std::size_t>(lead), seq_.frames.front());
      stats_.leading_frames += static_cast<std::uint64_t>(lead);
      anchor_index_ += lead;
      last_index_ += lead;
      while (static_cast<std::int64_t>(seq_.frames.size()) > max_frames_) {
        seq_.frames.pop_back();
        ++stats_.over_limit;
      }
    } else if (*k < first_index) {
      ++stats_.report_mismatches;
    }
  }
  if (!anchored_ || !sender_packets || stats_.discontinuities > 0) return;
  const std::int64_t target = static_cast<std::int64_t>(*sender_packets) - stats_.first_sender_frame;
  const std::int64_t missing = target - (last_index_ + 1);
  if (missing <= 0 || missing > max_gap()) return;
  for (std::int64_t i = 0; i < missing && !full(); ++i) {
    seq_.frames.push_back(seq_.frames.back());
    ++stats_.trailing_frames;
  }
  last_index_ += missing;
}

}  // namespace fapcast
