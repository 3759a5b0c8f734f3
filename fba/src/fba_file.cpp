#include "fapcast/fba/fba_file.hpp"

#include "fapcast/fba/fba_errc.hpp"
#include "fba_plan.hpp"
#include "fba_plane.hpp"
#include "fba_standard_planes.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <limits>
#include <optional>
#include <vector>

namespace fapcast {
namespace {

using detail::FapcastIntraHeader;
using detail::StandardIntraHeader;

constexpr std::array<std::uint8_t, 12> kFapcastOpening = {0x00, 0x00, 0x01, 0xB2, 'f', 'a', 'p', 'c', 'a', 's', 't', kFbaFapcastVersion};

[[noreturn]] void refuse(std::error_code code, const std::string& detail) {
  throw FbaEncodeError(code, "fba encode: " + detail);
}

void check(FbaProfile profile, const FapFrame& frame, int fap_quant, std::uint64_t index) {
  std::string detail;
  if (auto e = detail::check_codable(profile, frame, fap_quant, index, detail)) refuse(e, detail);
}

// The frames of the period that starts at k: up to `period` frames of one mask.
std::size_t nominal_end(const FapSequence& seq, std::size_t k, std::size_t period, FbaProfile profile, int q) {
  std::size_t end = k + 1;
  while (end < seq.frames.size() && end - k < period && seq.frames[end].mask == seq.frames[k].mask) {
    check(profile, seq.frames[end], q, end);
    ++end;
  }
  return end;
}

std::vector<std::uint8_t> encode_standard(const FapSequence& seq, const FbaEncoderOptions& o, const FbaRateFields& rate,
                                          FbaEncodeStats& stats) {
  FbaBitWriter out(FbaStuffing::kReference);
  out.start_code(kFbaObjectStartCode);
  FbaCodingState state;
  detail::StandardPlanes planes(out, state, stats.intra_planes, stats.predicted_planes, stats.recoded_for_decoders,
                                stats.not_read_alike);
  const auto period = static_cast<std::size_t>(fba_intra_period(o, seq.rate, true));
  bool inline_intra = false;  // an intra plane that replaces a P plane follows without a start code
  for (std::size_t k = 0; k < seq.frames.size();) {
    check(FbaProfile::kStandard, seq.frames[k], o.fap_quant, k);
    const std::size_t nominal = nominal_end(seq, k, period, FbaProfile::kStandard, o.fap_quant);
    detail::StandardPlan plan = detail::plan_standard_period(seq.frames, k, nominal, state, o.fap_quant, !inline_intra);
    plan.header.rate = rate;
    if (o.time_codes) plan.header.time_code = detail::fba_time_code(k, seq.rate);
    if (!inline_intra) planes.start_code(kFbaPlaneStartCode);
    planes.intra(seq.frames[k], plan.header, k + 1 == plan.end);
    inline_intra = false;
    std::size_t j = k + 1;
    for (; j < plan.end; ++j) {
      assert(seq.frames[j].mask == state.mask);
      if (!planes.predicted(seq.frames[j], j + 1 == plan.end)) break;
    }
    inline_intra = j < plan.end;
    k = j;
  }
  out.stuff_to_start_code();
  out.start_code(kFbaEndCode);
  stats.state_checksum = state.checksum();
  return std::move(out.bytes());
}

std::vector<std::uint8_t> encode_fapcast(const FapSequence& seq, const FbaEncoderOptions& o, const FbaRateFields& rate,
                                         FbaEncodeStats& stats) {
  FbaBitWriter out(FbaStuffing::kContinuous);
  out.start_code(kFbaUserDataStartCode);
  for (std::size_t i = 4; i < kFapcastOpening.size(); ++i) out.put(kFapcastOpening[i], 8);
  FbaCodingState state;
  state.profile = FbaProfile::kFapcast;
  const auto period = static_cast<std::size_t>(fba_intra_period(o, seq.rate, true));
  for (std::size_t k = 0; k < seq.frames.size();) {
    check(FbaProfile::kFapcast, seq.frames[k], o.fap_quant, k);
    const std::size_t end = nominal_end(seq, k, period, FbaProfile::kFapcast, o.fap_quant);
    FapcastIntraHeader header = detail::plan_fapcast_period(seq.frames, k, end, o.fap_quant, o.choose_predictors);
    header.rate = rate;
    header.frame_number = static_cast<std::uint16_t>(k);
    if (k > 0) out.stuff_to_start_code();
    out.start_code(kFbaPlaneStartCode);
    detail::write_plane(state, seq.frames[k], nullptr, &header, 0, out);
    ++stats.intra_planes;
    for (std::size_t j = k + 1; j < end; ++j) {
      detail::write_plane(state, seq.frames[j], nullptr, nullptr, 0, out);
      ++stats.predicted_planes;
    }
    k = end;
  }
  out.stuff_to_start_code();
  out.start_code(kFbaEndCode);
  stats.state_checksum = state.checksum();
  return std::move(out.bytes());
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

// Whether the raw bits [at, end) of `in` are next_start_code() stuffing: a 0, then 1s.
bool is_stuffing(const FbaBitReader& in, std::uint64_t at, std::uint64_t end) {
  if (end <= at || end - at > 8) return false;
  const std::span<const std::uint8_t> d = in.data();
  for (std::uint64_t p = at; p < end; ++p) {
    const int bit = (d[p / 8] >> (7 - p % 8)) & 1;
    if (bit != (p == at ? 0 : 1)) return false;
  }
  return true;
}

// Decodes the planes after the opening (`body` bytes) under one stuffing reading.
FbaDecodeResult decode_body(std::span<const std::uint8_t> bytes, std::size_t body, FbaProfile profile, FbaStuffing stuffing,
                            bool fixed_give_back = false) {
  FbaDecodeResult result;
  FbaDecodeReport& report = result.report;
  report.bytes = bytes.size();
  report.profile = profile;
  report.stuffing = stuffing;
  const auto note = [&](std::uint64_t offset, std::error_code code) {
    ++report.errors_total;
    if (report.errors.size() < FbaDecodeReport::kMaxReportedErrors) report.errors.push_back({offset, code});
  };
  std::vector<FapFrame>& frames = result.sequence.frames;
  FbaCodingState state;
  state.profile = profile;
  bool in_loss = false, ended = false;
  std::uint64_t planes = 0;
  std::uint64_t pending_lost = 0;  // planes met in corrupt runs since the last good run
  // Lost and skipped frames are held copies: together at most what the bytes could describe
  // (a plane is at least 4 bits and skips at most 255 frames in 8), so a small file cannot ask
  // for a huge output.
  const auto affordable = [&](std::uint64_t more) {
    return report.frames_lost + report.frames_skipped + more <= detail::kMaxSkipFrames + 32 * bytes.size();
  };
  const auto lose = [&](std::size_t slot, std::uint64_t count) {
    const FapFrame held = slot == 0 ? FapFrame{} : frames[slot - 1];
    frames.insert(frames.begin() + static_cast<std::ptrdiff_t>(slot), count, held);
    report.frames_lost += count;
  };
  std::size_t at = body;  // start of the region after the opening or a start code
  bool first_region = true;
  while (!ended) {
    const std::size_t next = find_start_code(bytes, at);
    const std::span<const std::uint8_t> region = bytes.subspan(at, next - at);
    // The planes of the region, then the stuffing before the next start code.
    FbaBitReader in(region, stuffing);
    in.set_fixed_give_back(fixed_give_back);
    const std::size_t first_slot = frames.size();
    std::uint64_t run_planes = 0, run_skipped = 0;
    detail::PlaneInfo first;
    std::error_code e;
    const bool opening_only = first_region && profile == FbaProfile::kFapcast && region.empty();
    while (!opening_only) {
      // next_start_code() stuffing ends the region: a 0, then 1s (no plane begins so: an intra
      // plane begins with a 1, a P plane's first two bits are 0 0 in the standard syntax, and one
      // of the fapcast profile that begins 0 1 1 ... needs more than 8 bits).
      const std::uint64_t left = in.size_bits() - in.position().raw_bits;
      if (is_stuffing(in, in.position().raw_bits, in.size_bits())) break;
      if (left == 0) {
        if (next < bytes.size() && !opening_only) {
          e = fba_errc::bad_stuffing;  // a start code right after a plane, without stuffing
          in.fail(e);
        }
        break;  // else the data ends here (no end code: reported below)
      }
      ++run_planes;
      ++planes;
      detail::PlaneInfo info;
      e = detail::read_plane(state, in, frames.emplace_back(), info);  // decoded in place
      if (e && left <= 8 && next < bytes.size()) {
        e = fba_errc::bad_stuffing;  // the bits before a start code are no plane and no stuffing
        in.fail(e);
      }
      if (!e && !affordable(run_skipped + static_cast<std::uint64_t>(info.skip_frames))) {
        e = fba_errc::skip_too_long;  // more held frames than the file could justify
        in.fail(e);
      }
      if (e) break;
      if (run_planes == 1) first = info;
      if (info.intra && info.rate) report.rate_known = true;
      if (info.intra) report.fap_quant = state.fap_quant;
      if (info.time_code) {
        // The plane's time truncated to the second, as the running count of frames says.
        const detail::FbaTimeCode expected = detail::fba_time_code(frames.size() - 1, state.rate);
        if (!(expected == *info.time_code)) ++report.time_code_mismatches;
      }
      if (info.skip_frames > 0) {  // the frame is held for the skipped periods after it
        const FapFrame held = frames.back();
        frames.insert(frames.end(), static_cast<std::size_t>(info.skip_frames), held);
      }
      run_skipped += static_cast<std::uint64_t>(info.skip_frames);
    }
    if (e) {
      state.have_intra = false;
      state.ranges = {};  // what the lost planes set is unknown: the next intra plane starts from the defaults
      state.blend_levels = fba_blend_levels(0);
      frames.resize(first_slot);  // a corrupt run is lost whole: its frames cannot be trusted
      // P planes refused after a loss are part of that loss, not new errors.
      if (!(in_loss && e == fba_errc::predicted_without_intra)) note(at + in.error_bits() / 8, e);
      in_loss = true;
      pending_lost += std::max<std::uint64_t>(run_planes, 1);
    } else if (run_planes > 0) {
      // A good run. fapcast: its intra plane's frame_number says where it lands, so how many
      // frames were lost; standard: the planes met since the loss.
      if (profile == FbaProfile::kFapcast && first.intra) {
        const std::uint64_t slot = first_slot;
        const std::uint64_t gap = static_cast<std::uint16_t>(first.frame_number - static_cast<std::uint16_t>(slot));
        std::uint64_t lost = in_loss ? pending_lost : 0;
        if (gap != 0 && !in_loss) note(at, fba_errc::bad_frame_number);  // a run went missing whole
        if ((gap != 0 || in_loss) && affordable(gap)) {
          lost = gap;
        } else if (gap != 0 && in_loss) {
          note(at, fba_errc::bad_frame_number);
        }
        if (lost > 0 && affordable(lost)) lose(first_slot, lost);
      } else if (in_loss && affordable(pending_lost)) {
        lose(first_slot, pending_lost);
      }
      if (report.frames_decoded == 0 && next > 0) {
        // The first good run says about how many frames a byte holds: room for the whole file at
        // that rate saves growing the output (never more than the file could describe).
        const std::uint64_t estimate = frames.size() * bytes.size() / next;
        frames.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(estimate + estimate / 16, detail::kMaxSkipFrames + 2 * bytes.size())));
      }
      in_loss = false;
      pending_lost = 0;
      report.frames_decoded += run_planes;
      report.frames_skipped += run_skipped;
    }
    first_region = false;
    if (next >= bytes.size()) {
      note(bytes.size(), fba_errc::missing_end_code);
      break;
    }
    const std::uint8_t code = next + 3 < bytes.size() ? bytes[next + 3] : 0;
    if (code == (kFbaEndCode & 0xFF)) {
      ended = true;
      if (next + 4 < bytes.size()) note(next + 4, fba_errc::trailing_bytes);
    } else if (code != (kFbaPlaneStartCode & 0xFF)) {
      note(next, next + 3 < bytes.size() ? make_error_code(fba_errc::bad_start_code) : make_error_code(fba_errc::truncated));
      state.have_intra = false;
      in_loss = true;
      ++pending_lost;
    }
    at = std::min(next + 4, bytes.size());
  }
  if (in_loss && affordable(pending_lost)) lose(frames.size(), pending_lost);
  result.sequence.rate = state.rate;
  report.state_checksum = state.checksum();
  return result;
}

}  // namespace

int fba_intra_period(const FbaEncoderOptions& o, FrameRate rate, bool whole_file) {
  if (o.intra_period > 0) return o.intra_period;
  const std::uint64_t seconds = !whole_file ? 1 : o.profile == FbaProfile::kStandard ? 10 : kFbaArchiveIntraSeconds;
  const std::uint64_t frames = rate.valid() ? seconds * rate.numerator / rate.denominator : 25;
  return static_cast<int>(std::clamp<std::uint64_t>(frames, 1, std::numeric_limits<int>::max()));
}

std::vector<std::uint8_t> encode_fba(const FapSequence& seq, const FbaEncoderOptions& o, FbaEncodeStats* stats) {
  if (o.fap_quant < 0 || o.fap_quant > kMaxFapQuant || o.intra_period < 0)
    refuse(std::make_error_code(std::errc::invalid_argument),
           "options: fap_quant must be 0..31 (got " + std::to_string(o.fap_quant) +
               ") and intra_period >= 0 (got " + std::to_string(o.intra_period) + ")");
  const auto rate = fba_rate_fields(seq.rate);
  if (!rate) refuse(fba_errc::uncodable_frame_rate, "frame rate has no frame_rate(8) + seconds(4)/16 form");
  FbaEncodeStats local;
  FbaEncodeStats& s = stats ? *stats : local;
  s = {};
  return o.profile == FbaProfile::kStandard ? encode_standard(seq, o, *rate, s) : encode_fapcast(seq, o, *rate, s);
}

std::optional<std::string> fba_standard_refusal(const FapSequence& seq, int fap_quant) {
  std::string detail;
  for (std::size_t k = 0; k < seq.frames.size(); ++k)
    if (detail::check_codable(FbaProfile::kStandard, seq.frames[k], fap_quant, k, detail)) return detail;
  return std::nullopt;
}

FbaEncoderOptions fba_archive_options(FbaProfile profile, int fap_quant, FrameRate rate) {
  const std::uint64_t frames = rate.valid() ? std::uint64_t{kFbaArchiveIntraSeconds} * rate.numerator / rate.denominator : 1;
  FbaEncoderOptions o;
  o.profile = profile;
  o.fap_quant = fap_quant;
  o.intra_period = static_cast<int>(std::clamp<std::uint64_t>(frames, 1, std::numeric_limits<int>::max()));
  return o;
}

std::span<const std::uint8_t> fba_fapcast_opening() { return kFapcastOpening; }

std::optional<FbaProfile> fba_file_profile(std::span<const std::uint8_t> b) {
  if (b.size() >= 4 && b[0] == 0 && b[1] == 0 && b[2] == 1 && b[3] == (kFbaObjectStartCode & 0xFF)) return FbaProfile::kStandard;
  if (b.size() >= kFapcastOpening.size() - 1 && std::equal(kFapcastOpening.begin(), kFapcastOpening.end() - 1, b.begin()))
    return FbaProfile::kFapcast;
  return std::nullopt;
}

std::string FbaDecodeError::message() const {
  return "byte " + std::to_string(byte_offset) + ": " + code.message();
}

FbaDecodeResult decode_fba(std::span<const std::uint8_t> bytes, const FbaDecodeOptions& options) {
  const std::optional<FbaProfile> profile = fba_file_profile(bytes);
  const auto refused = [&](std::error_code e) {
    FbaDecodeResult r;
    r.report.bytes = bytes.size();
    r.report.errors_total = 1;
    r.report.errors.push_back({0, e});
    return r;
  };
  if (!profile) return refused(fba_errc::missing_object_start_code);
  if (*profile == FbaProfile::kFapcast) {
    if (options.standard_only) {
      FbaDecodeResult r = refused(fba_errc::fapcast_profile);
      r.report.profile = FbaProfile::kFapcast;
      return r;
    }
    if (bytes.size() < kFapcastOpening.size() || bytes[kFapcastOpening.size() - 1] != kFbaFapcastVersion)
      return refused(fba_errc::bad_profile_version);
    return decode_body(bytes, kFapcastOpening.size(), FbaProfile::kFapcast, FbaStuffing::kContinuous);
  }
  if (options.stuffing) return decode_body(bytes, 4, FbaProfile::kStandard, *options.stuffing, options.fixed_give_back);
  FbaDecodeResult r = decode_body(bytes, 4, FbaProfile::kStandard, FbaStuffing::kReference, options.fixed_give_back);
  if (r.report.ok()) return r;
  FbaDecodeResult c = decode_body(bytes, 4, FbaProfile::kStandard, FbaStuffing::kContinuous);
  return c.report.ok() ? c : r;
}

}  // namespace fapcast
