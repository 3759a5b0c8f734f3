#include "fapcast/codec/fba_file.hpp"

#include "fapcast/codec/fba_errc.hpp"
#include "fba_plane.hpp"

#include <cassert>

namespace fapcast::codec {
namespace {

using detail::IntraHeader;
using detail::LevelExtremes;

[[noreturn]] void refuse(std::error_code code, const std::string& detail) {
  throw FbaEncodeError(code, "fba encode: " + detail);
}

void check(const FapFrame& frame, int fap_quant, std::uint64_t index) {
  std::string detail;
  if (auto e = detail::check_codable(frame, fap_quant, index, detail)) refuse(e, detail);
}

// Plans the intra period that starts at frame k: the intra header (ranges sized to the
// frames it heads) and the end of the period (exclusive). The period ends at intra_period
// frames, at a mask change, or before a P difference no 5-bit field reaches.
std::size_t plan_intra_period(const std::vector<FapFrame>& frames, std::size_t k,
                              const FbaEncoderOptions& o, IntraHeader& header) {
  const FapFrame& first = frames[k];
  const int q = o.fap_quant;
  const detail::FbaLevels levels = detail::intra_levels(first, q);
  header.fap_quant = q;
  header.ranges = detail::intra_range_fields(levels, first.mask, q);
  std::array<std::int32_t, kFapCount> reconstructed{};
  detail::reconstruct(reconstructed, levels, first.mask, q, true);
  LevelExtremes extremes;
  std::size_t end = k + 1;
  const auto period = static_cast<std::size_t>(o.intra_period);
  while (end < frames.size() && end - k < period && frames[end].mask == first.mask) {
    check(frames[end], q, end);
    const detail::FbaLevels d = detail::predicted_levels(reconstructed, q, frames[end]);
    LevelExtremes trial = extremes;
    trial.add(d);
    auto ranges = header.ranges;
    if (!detail::size_predicted_fields(trial, first.mask, q, ranges)) break;
    extremes = trial;
    detail::reconstruct(reconstructed, d, first.mask, q, false);
    ++end;
  }
  const bool sized = detail::size_predicted_fields(extremes, first.mask, q, header.ranges);
  assert(sized);
  (void)sized;
  return end;
}

std::size_t find_start_code(std::span<const std::uint8_t> b, std::size_t from) {
  for (std::size_t i = from; i + 2 < b.size(); ++i) {
    if (b[i + 2] > 1) {
      i += 2;  // no prefix can start at i, i+1 or i+2
    } else if (b[i] == 0 && b[i + 1] == 0 && b[i + 2] == 1) {
      return i;
    }
  }
  return b.size();
}

}  // namespace

std::vector<std::uint8_t> encode_fba(const FapSequence& seq, const FbaEncoderOptions& o) {
  if (o.fap_quant < 0 || o.fap_quant > kMaxFapQuant || o.intra_period < 1)
    refuse(std::make_error_code(std::errc::invalid_argument),
           "options: fap_quant must be 0..31 (got " + std::to_string(o.fap_quant) +
               ") and intra_period >= 1 (got " + std::to_string(o.intra_period) + ")");
  const auto rate = fba_rate_fields(seq.rate);
  if (!rate) refuse(fba_errc::uncodable_frame_rate, "frame rate has no frame_rate(8)/seconds(4) form");
  FbaBitWriter out;
  out.start_code(kFbaObjectStartCode);
  FbaCodingState state;
  for (std::size_t k = 0; k < seq.frames.size();) {
    check(seq.frames[k], o.fap_quant, k);
    IntraHeader header;
    header.rate = *rate;
    const std::size_t end = plan_intra_period(seq.frames, k, o, header);
    detail::write_plane(state, seq.frames[k], &header, out);
    for (std::size_t j = k + 1; j < end; ++j) {
      assert(detail::levels_fit(detail::predicted_levels(state.reconstructed, state.fap_quant, seq.frames[j]),
                                seq.frames[j].mask, state, false));
      detail::write_plane(state, seq.frames[j], nullptr, out);
    }
    k = end;
  }
  out.start_code(kFbaEndCode);
  return std::move(out.bytes());
}

std::string FbaDecodeError::message() const {
  return "byte " + std::to_string(byte_offset) + ": " + code.message();
}

FbaDecodeResult decode_fba(std::span<const std::uint8_t> bytes) {
  FbaDecodeResult result;
  FbaDecodeReport& report = result.report;
  report.bytes = bytes.size();
  const auto note = [&](std::uint64_t offset, std::error_code code) {
    ++report.errors_total;
    if (report.errors.size() < FbaDecodeReport::kMaxReportedErrors) report.errors.push_back({offset, code});
  };
  std::vector<FapFrame>& frames = result.sequence.frames;
  const auto hold = [&] { frames.push_back(frames.empty() ? FapFrame{} : frames.back()); };

  std::size_t at = find_start_code(bytes, 0);
  if (at != 0 || bytes.size() < 4 || bytes[3] != (kFbaObjectStartCode & 0xFF)) {
    note(0, fba_errc::missing_object_start_code);
  } else {
    at = find_start_code(bytes, 4);
    if (at > 4) note(4, fba_errc::trailing_bytes);  // bits between the object start code and the first plane
  }

  FbaCodingState state;
  detail::PlaneInfo info;
  bool rate_known = false, in_loss = false, ended = false;
  std::uint64_t planes = 0;
  while (at < bytes.size() && !ended) {
    const std::size_t next = find_start_code(bytes, at + 3);
    const std::span<const std::uint8_t> unit = bytes.subspan(at, next - at);
    const std::uint8_t code = unit.size() >= 4 ? unit[3] : 0;
    if (unit.size() >= 4 && code == (kFbaEndCode & 0xFF)) {
      ended = true;
      if (unit.size() > 4 || next < bytes.size()) note(at + 4, fba_errc::trailing_bytes);
    } else if (unit.size() < 4 || code != (kFbaPlaneStartCode & 0xFF)) {
      note(at, unit.size() < 4 ? make_error_code(fba_errc::truncated) : make_error_code(fba_errc::bad_start_code));
      ++report.frames_lost;
      hold();
      in_loss = true;
      state.have_intra = false;
    } else {
      ++planes;
      FapFrame frame;
      std::error_code e = detail::read_plane(state, unit, frame, info);
      if (!e && report.frames_skipped + static_cast<std::uint64_t>(info.skip_frames) >
                    detail::kMaxSkipFrames + planes) {
        e = fba_errc::skip_too_long;  // more held frames than the file could justify
        state.have_intra = false;
      }
      if (e) {
        // P planes refused after a loss are part of that loss, not new errors.
        if (!(in_loss && e == fba_errc::predicted_without_intra)) note(at + info.error_bit / 8, e);
        in_loss = true;
        ++report.frames_lost;
        hold();
      } else {
        in_loss = false;
        if (!rate_known) result.sequence.rate = state.rate;
        rate_known = true;
        for (int i = 0; i < info.skip_frames; ++i) hold();
        report.frames_skipped += static_cast<std::uint64_t>(info.skip_frames);
        frames.push_back(frame);
        ++report.frames_decoded;
      }
    }
    at = next;
  }
  if (!ended) note(bytes.size(), fba_errc::missing_end_code);
  return result;
}

}  // namespace fapcast::codec
