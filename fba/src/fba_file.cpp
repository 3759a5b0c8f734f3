#include "fapcast/fba/fba_file.hpp"

#include "fapcast/fba/fba_errc.hpp"
#include "fba_plane.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <limits>
#include <optional>
#include <vector>

namespace fapcast {
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

// log2(x) in 1/256 bit for x >= 1, interpolated linearly between powers of two (at most 0.09
// bit low; integers only, so every platform chooses alike).
std::int64_t log2_q8(std::uint32_t x) {
  const int e = std::bit_width(x) - 1;
  return std::int64_t{e} * 256 + ((std::int64_t{x} - (std::int64_t{1} << e)) * 256 >> e);
}

// About the bits the P levels `levels` of one FAP cost: the smallest P range fields covering
// them, and the adaptive model over that range coding them one after another (in 1/256 bit).
// Stops counting past `enough`; nullopt when no 5-bit field covers them.
std::optional<std::int64_t> predicted_cost(const std::vector<std::int32_t>& levels, int q, std::int64_t enough) {
  std::int32_t lo = 0, hi = 0;
  for (const std::int32_t l : levels) {
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  const auto min_field = fba_range_field(-std::int64_t{lo}, q), max_field = fba_range_field(hi, q);
  if (!min_field || !max_field) return std::nullopt;
  const int offset = fba_range_levels(*min_field, q);
  FrequencyModel model(offset + fba_range_levels(*max_field, q) + 1);
  std::int64_t cost = 0;
  for (std::size_t j = 0; j < levels.size() && cost < enough; ++j) {
    const int s = levels[j] + offset;
    cost += log2_q8(model.total()) - log2_q8(model.cumulative(s) - model.cumulative(s + 1));
    model.update(s);
  }
  return cost;
}

// fapcast: the predictor of each FAP for the P planes of frames [k + 1, end), chosen by coding
// them closed loop with every predictor and costing the levels as the adaptive model would
// (predicted_cost). All 0 (no predictor fields sent) unless the choice saves more than the
// fields cost.
std::array<std::uint8_t, kFapCount> choose_predictors(const std::vector<FapFrame>& frames, std::size_t k,
                                                      std::size_t end, const FapMask& mask, int q) {
  std::array<std::uint8_t, kFapCount> best{};
  std::int64_t saved = 0, fields = 256;  // 1/256 bit: the is_predictor flag, then 5 bits a FAP
  std::vector<std::int32_t> levels;
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (!mask.test(n)) continue;
    fields += 5 * 256;
    const std::size_t i = static_cast<std::size_t>(n - 1);
    const int step = fba_step(n, q);
    constexpr std::int64_t kUncodable = std::numeric_limits<std::int64_t>::max();
    std::int64_t plain = 0, best_cost = kUncodable;
    for (int predictor = 0; predictor <= kMaxPredictor; ++predictor) {
      const std::int32_t first = fba_quantise(frames[k].values[i], step) * step;
      std::int32_t r1 = first, r2 = first, r3 = first;
      levels.clear();
      for (std::size_t j = k + 1; j < end; ++j) {
        const std::int32_t p = fba_predict(predictor, r1, r2, r3);
        const std::int32_t level = fba_quantise(std::int64_t{frames[j].values[i]} - p, step);
        levels.push_back(level);
        r3 = r2;
        r2 = r1;
        r1 = static_cast<std::int32_t>(std::clamp<std::int64_t>(std::int64_t{p} + std::int64_t{level} * step, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()));
      }
      const std::int64_t cost = predicted_cost(levels, q, best_cost).value_or(kUncodable);
      if (predictor == 0) {
        plain = best_cost = cost;
      } else if (cost < best_cost) {
        best_cost = cost;
        best[i] = static_cast<std::uint8_t>(predictor);
      }
    }
    saved += std::min(plain - best_cost, std::int64_t{1} << 40);  // plain may be uncodable (the period is cut then)
  }
  if (saved <= fields) best = {};
  return best;
}

// Plans the intra period that starts at frame k: the intra header (ranges sized to the
// frames it heads, predictors chosen for them) and the end of the period (exclusive). The period
// ends at intra_period frames, at a mask change, or before a P difference no 5-bit field reaches.
std::size_t plan_intra_period(const std::vector<FapFrame>& frames, std::size_t k,
                              const FbaEncoderOptions& o, IntraHeader& header) {
  const FapFrame& first = frames[k];
  const int q = o.fap_quant;
  const auto period = static_cast<std::size_t>(o.intra_period);
  std::size_t nominal_end = k + 1;
  while (nominal_end < frames.size() && nominal_end - k < period && frames[nominal_end].mask == first.mask) {
    check(frames[nominal_end], q, nominal_end);
    ++nominal_end;
  }
  const detail::FbaLevels levels = detail::intra_levels(first, q);
  header.fap_quant = q;
  header.ranges = detail::intra_range_fields(levels, first.mask, q);
  if (o.choose_predictors) header.predictors = choose_predictors(frames, k, nominal_end, first.mask, q);
  header.frame_number = static_cast<std::uint16_t>(k);
  FbaPrediction prediction;
  prediction.predictor = header.predictors;
  const FbaCodedFaps faps(first.mask, header.ranges, q);  // the steps (the P ranges come below)
  detail::reconstruct(prediction, levels, faps, true);
  LevelExtremes extremes;
  std::size_t end = k + 1;
  while (end < nominal_end) {
    const detail::FbaLevels d = detail::predicted_levels(prediction, faps, frames[end]);
    LevelExtremes trial = extremes;
    trial.add(d);
    auto ranges = header.ranges;
    if (!detail::size_predicted_fields(trial, first.mask, q, ranges)) break;
    extremes = trial;
    detail::reconstruct(prediction, d, faps, false);
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
    // One run: a start code, the intra plane, its P planes packed after it, alignment.
    out.start_code(kFbaPlaneStartCode);
    detail::write_plane(state, seq.frames[k], &header, out);
    for (std::size_t j = k + 1; j < end; ++j) {
      assert(seq.frames[j].mask == state.mask &&
             detail::levels_fit(detail::predicted_levels(state.prediction, state.coded, seq.frames[j]), state.coded, false));
      detail::write_plane(state, seq.frames[j], nullptr, out);
    }
    out.align();
    k = end;
  }
  out.start_code(kFbaEndCode);
  return std::move(out.bytes());
}

FbaEncoderOptions fba_archive_options(int fap_quant, FrameRate rate) {
  const std::uint64_t frames = rate.valid() ? std::uint64_t{kFbaArchiveIntraSeconds} * rate.numerator / rate.denominator : 1;
  const auto period = static_cast<int>(std::clamp<std::uint64_t>(frames, 1, std::numeric_limits<int>::max()));
  return {.fap_quant = fap_quant, .intra_period = period, .choose_predictors = true};
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

  std::size_t at = find_start_code(bytes, 0);
  if (at != 0 || bytes.size() < 4 || bytes[3] != (kFbaObjectStartCode & 0xFF)) {
    note(0, fba_errc::missing_object_start_code);
  } else {
    at = find_start_code(bytes, 4);
    if (at > 4) note(4, fba_errc::trailing_bytes);  // bits between the object start code and the first plane
  }

  FbaCodingState state;
  bool rate_known = false, in_loss = false, ended = false;
  std::uint64_t planes = 0;
  std::uint64_t pending_lost = 0;  // planes met in corrupt runs since the last good run
  // Lost and skipped frames are held copies: together at most what the bytes could describe
  // (a plane is at least 4 bits), so a small file cannot ask for a huge output.
  const auto affordable = [&](std::uint64_t more) {
    return report.frames_lost + report.frames_skipped + more <= detail::kMaxSkipFrames + 2 * bytes.size();
  };
  const auto lose = [&](std::size_t slot, std::uint64_t count) {
    const FapFrame held = slot == 0 ? FapFrame{} : frames[slot - 1];
    frames.insert(frames.begin() + static_cast<std::ptrdiff_t>(slot), count, held);
    report.frames_lost += count;
  };
  while (at < bytes.size() && !ended) {
    const std::size_t next = find_start_code(bytes, at + 3);
    const std::span<const std::uint8_t> unit = bytes.subspan(at, next - at);
    const std::uint8_t code = unit.size() >= 4 ? unit[3] : 0;
    if (unit.size() >= 4 && code == (kFbaEndCode & 0xFF)) {
      ended = true;
      if (unit.size() > 4 || next < bytes.size()) note(at + 4, fba_errc::trailing_bytes);
      at = next;
      continue;
    }
    if (unit.size() < 4 || code != (kFbaPlaneStartCode & 0xFF)) {
      note(at, unit.size() < 4 ? make_error_code(fba_errc::truncated) : make_error_code(fba_errc::bad_start_code));
      ++pending_lost;
      in_loss = true;
      state.have_intra = false;
      at = next;
      continue;
    }
    // A run: planes back to back after one start code. A P plane begins with is_intra = 0; a 1
    // where a plane could begin is the first alignment bit.
    FbaBitReader in(unit.subspan(4));
    const std::size_t first_slot = frames.size();
    std::uint64_t run_planes = 0, run_skipped = 0;
    detail::PlaneInfo first;
    std::error_code e;
    for (;;) {
      ++run_planes;
      ++planes;
      detail::PlaneInfo info;
      e = detail::read_plane(state, in, frames.emplace_back(), info);  // decoded in place
      if (!e && report.frames_skipped + run_skipped + static_cast<std::uint64_t>(info.skip_frames) >
                    detail::kMaxSkipFrames + planes) {
        e = fba_errc::skip_too_long;  // more held frames than the file could justify
        in.fail(e);
      }
      if (e) break;
      if (run_planes == 1) first = info;
      if (info.skip_frames > 0) {  // held copies of the frame before, ahead of the new one
        const FapFrame held = frames.size() >= 2 ? frames[frames.size() - 2] : FapFrame{};
        frames.insert(frames.end() - 1, static_cast<std::size_t>(info.skip_frames), held);
      }
      run_skipped += static_cast<std::uint64_t>(info.skip_frames);
      if (in.at_end()) break;
      if (in.peek_bit() == 1) {
        in.expect_end();
        e = in.error();
        break;
      }
    }
    if (e) {
      state.have_intra = false;
      frames.resize(first_slot);  // a corrupt run is lost whole: its frames cannot be trusted
      // P planes refused after a loss are part of that loss, not new errors.
      if (!(in_loss && e == fba_errc::predicted_without_intra)) note(at + 4 + in.error_bits() / 8, e);
      in_loss = true;
      pending_lost += run_planes;
      at = next;
      continue;
    }
    // A good run. Its intra plane's frame_number says where it lands, so how many were lost.
    if (first.intra) {
      const std::uint64_t slot = first_slot + static_cast<std::uint64_t>(first.skip_frames);
      const std::uint64_t gap = static_cast<std::uint16_t>(first.frame_number - static_cast<std::uint16_t>(slot));
      std::uint64_t lost = in_loss ? pending_lost : 0;
      if (gap != 0 && !in_loss) note(at + 4, fba_errc::bad_frame_number);  // a run went missing whole
      if ((gap != 0 || in_loss) && affordable(gap)) {
        lost = gap;
      } else if (gap != 0 && in_loss) {
        note(at + 4, fba_errc::bad_frame_number);
      }
      if (lost > 0 && affordable(lost)) lose(first_slot, lost);
    } else if (in_loss && affordable(pending_lost)) {
      lose(first_slot, pending_lost);
    }
    if (report.frames_decoded == 0) {
      // The first good run says about how many frames a byte holds: room for the whole file at
      // that rate saves growing the output (never more than the file could describe).
      const std::uint64_t estimate = frames.size() * bytes.size() / next;
      frames.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(estimate + estimate / 16, detail::kMaxSkipFrames + 2 * bytes.size())));
    }
    in_loss = false;
    pending_lost = 0;
    report.frames_decoded += run_planes;
    report.frames_skipped += run_skipped;
    if (!rate_known) result.sequence.rate = state.rate;
    rate_known = true;
    at = next;
  }
  if (in_loss && affordable(pending_lost)) lose(frames.size(), pending_lost);
  if (!ended) note(bytes.size(), fba_errc::missing_end_code);
  return result;
}

}  // namespace fapcast
