#include "fba_plane.hpp"

#include "fapcast/fba/fba_errc.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

namespace fapcast::detail {
namespace {

constexpr int kObjectMaskFap = 1;  // fba_object_mask: 1 = FAP (2 = body is not implemented)
enum MaskType : std::uint32_t { kMaskNone = 0, kMaskBits = 1, kMaskBitsAlt = 2, kMaskAll = 3 };
constexpr int kMarkerEvery = 4;  // a marker bit before every 4th range field of a group

std::size_t at(int fap) { return static_cast<std::size_t>(fap - 1); }

// --- plane header -----------------------------------------------------------------------------

void write_group_masks(const FapMask& mask, FbaBitWriter& out) {
  for (int g = 1; g <= kGroupCount; ++g) {
    const FapRange faps = fap_group(g);
    int on = 0;
    for (int n = faps.first; n <= faps.last; ++n) on += mask.test(n);
    out.put_bit(1);  // marker
    if (on == 0) {
      out.put(kMaskNone, 2);
    } else if (on == faps.last - faps.first + 1) {
      out.put(kMaskAll, 2);
    } else {
      out.put(kMaskBits, 2);
      for (int n = faps.first; n <= faps.last; ++n) out.put_bit(mask.test(n));
    }
  }
}

FapMask read_group_masks(FbaBitReader& in) {
  FapMask mask;
  for (int g = 1; g <= kGroupCount; ++g) {
    const FapRange faps = fap_group(g);
    in.marker();
    const std::uint32_t type = in.get(2);
    for (int n = faps.first; n <= faps.last; ++n) {
      if (type == kMaskAll) mask.set(n);
      if (type == kMaskBits || type == kMaskBitsAlt) mask.set(n, in.get_bit() == 1);
    }
  }
  return mask;
}

// The range fields, flag by flag (i_max, i_min, p_max, p_min), each over the masked FAPs 3..68.
template <typename Visit>
void for_each_range_field(const FapMask& mask, Visit&& visit) {
  for (int flag = 0; flag < 4; ++flag) {
    for (int g = 2; g <= kGroupCount; ++g) {
      const FapRange faps = fap_group(g);
      int in_group = 0;
      for (int n = faps.first; n <= faps.last; ++n) {
        if (!mask.test(n)) continue;
        visit(flag, n, in_group % kMarkerEvery == kMarkerEvery - 1);
        ++in_group;
      }
    }
  }
}

std::uint8_t& field(FbaRangeFields& r, int flag) {
  switch (flag) {
    case 0: return r.i_max;
    case 1: return r.i_min;
    case 2: return r.p_max;
    default: return r.p_min;
  }
}

// --- segments -----------------------------------------------------------------------------------

void write_segments(FbaCodingState& s, const FapFrame& frame, bool intra, FbaBitWriter& out) {
  FbaModels& m = intra ? s.intra : s.predicted;
  if (frame.mask.test(kVisemeFap)) {
    ArithmeticEncoder ac(out);
    ac.encode(frame.viseme.select1, m.viseme_select1);
    ac.encode(frame.viseme.select2, m.viseme_select2);
    ac.encode(frame.viseme.blend, m.viseme_blend);
    ac.flush();
    out.put_bit(frame.viseme.def);
    s.viseme = frame.viseme;
  }
  if (frame.mask.test(kExpressionFap)) {
    ArithmeticEncoder ac(out);
    ac.encode(frame.expression.select1, m.expression_select1);
    ac.encode(frame.expression.intensity1, m.expression_intensity1);
    ac.encode(frame.expression.select2, m.expression_select2);
    ac.encode(frame.expression.intensity2, m.expression_intensity2);
    ac.flush();
    out.put_bit(frame.expression.init_face);
    out.put_bit(frame.expression.def);
    s.expression = frame.expression;
  }
  const FbaLevels levels = intra ? intra_levels(frame, s.fap_quant) : predicted_levels(s.prediction, s.coded, frame);
  if (!s.coded.empty()) {
    ArithmeticEncoder ac(out);
    for (const FbaCodedFap& f : s.coded) ac.encode(levels[f.index] - (intra ? f.intra_min : f.predicted_min), m.fap[f.index]);
    ac.flush();
  }
  reconstruct(s.prediction, levels, s.coded, intra);
}

void read_segments(FbaCodingState& s, bool intra, FbaBitReader& in, FapFrame& out) {
  FbaModels& m = intra ? s.intra : s.predicted;
  out = FapFrame{};
  out.mask = s.mask;
  if (s.mask.test(kVisemeFap)) {
    ArithmeticDecoder ad(in);
    out.viseme.select1 = static_cast<std::uint8_t>(ad.decode(m.viseme_select1));
    out.viseme.select2 = static_cast<std::uint8_t>(ad.decode(m.viseme_select2));
    out.viseme.blend = static_cast<std::uint8_t>(ad.decode(m.viseme_blend));
    ad.finish();
    out.viseme.def = in.get_bit() == 1;
    s.viseme = out.viseme;
  }
  if (s.mask.test(kExpressionFap)) {
    ArithmeticDecoder ad(in);
    out.expression.select1 = static_cast<std::uint8_t>(ad.decode(m.expression_select1));
    out.expression.intensity1 = static_cast<std::uint8_t>(ad.decode(m.expression_intensity1));
    out.expression.select2 = static_cast<std::uint8_t>(ad.decode(m.expression_select2));
    out.expression.intensity2 = static_cast<std::uint8_t>(ad.decode(m.expression_intensity2));
    ad.finish();
    out.expression.init_face = in.get_bit() == 1;
    out.expression.def = in.get_bit() == 1;
    s.expression = out.expression;
  }
  if (s.coded.empty()) return;
  ArithmeticDecoder ad(in);
  for (const FbaCodedFap& f : s.coded) {
    reconstruct(s.prediction, f, ad.decode(m.fap[f.index]) + (intra ? f.intra_min : f.predicted_min), intra);
    out.values[f.index] = s.prediction.r1[f.index];
  }
  ad.finish();
}

}  // namespace

// --- quantisation and ranges --------------------------------------------------------------------

FbaLevels intra_levels(const FapFrame& frame, int fap_quant) {
  FbaLevels levels{};
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (frame.mask.test(n)) levels[at(n)] = fba_quantise(frame.values[at(n)], fba_step(n, fap_quant));
  }
  return levels;
}

FbaLevels predicted_levels(const FbaPrediction& p, const FbaCodedFaps& faps, const FapFrame& frame) {
  FbaLevels levels{};
  for (const FbaCodedFap& f : faps) {
    const std::size_t i = f.index;
    const std::int64_t error = std::int64_t{frame.values[i]} - fba_predict(p.predictor[i], p.r1[i], p.r2[i], p.r3[i]);
    levels[i] = fba_quantise(error, f.step);
  }
  return levels;
}

void reconstruct(FbaPrediction& p, const FbaLevels& levels, const FbaCodedFaps& faps, bool intra) {
  for (const FbaCodedFap& f : faps) reconstruct(p, f, levels[f.index], intra);
}

bool levels_fit(const FbaLevels& levels, const FbaCodedFaps& faps, bool intra) {
  for (const FbaCodedFap& f : faps) {
    const std::int32_t level = levels[f.index];
    if (level < (intra ? f.intra_min : f.predicted_min) || level > (intra ? f.intra_max : f.predicted_max)) return false;
  }
  return true;
}

std::error_code check_codable(const FapFrame& frame, int fap_quant, std::uint64_t frame_index,
                              std::string& detail) {
  std::ostringstream msg;
  msg << "frame " << frame_index << ", ";
  const auto refuse = [&](const std::string& what) {
    msg << what << " (refused, never clipped)";
    detail = msg.str();
    return make_error_code(fba_errc::uncodable_value);
  };
  if (frame.mask.test(kVisemeFap)) {
    const VisemeField& v = frame.viseme;
    if (v.select1 > 14 || v.select2 > 14 || v.blend > 63)
      return refuse("FAP 1 viseme: select1/select2 must be 0..14 and blend 0..63");
  }
  if (frame.mask.test(kExpressionFap)) {
    const ExpressionField& e = frame.expression;
    if (e.select1 > 6 || e.select2 > 6 || e.intensity1 > 63 || e.intensity2 > 63)
      return refuse("FAP 2 expression: selects must be 0..6 and intensities 0..63");
  }
  const int max_levels = fba_range_levels(kMaxRangeField, fap_quant);
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (!frame.mask.test(n)) continue;
    const int step = fba_step(n, fap_quant);
    const std::int32_t level = fba_quantise(frame.values[at(n)], step);
    if (level > max_levels || level < -max_levels) {
      msg << "FAP " << n << " " << fap_info(n).name << ": value " << frame.values[at(n)]
          << " is beyond the codable range +/-" << std::int64_t{max_levels} * step << " at fap_quant "
          << fap_quant;
      return refuse("");
    }
  }
  return {};
}

std::array<FbaRangeFields, kFapCount> intra_range_fields(const FbaLevels& levels, const FapMask& mask,
                                                         int fap_quant) {
  std::array<FbaRangeFields, kFapCount> ranges{};
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (!mask.test(n)) continue;
    const std::int32_t level = levels[at(n)];
    ranges[at(n)].i_max = static_cast<std::uint8_t>(fba_range_field(std::max(level, 0), fap_quant).value_or(kMaxRangeField));
    ranges[at(n)].i_min = static_cast<std::uint8_t>(fba_range_field(std::max(-level, 0), fap_quant).value_or(kMaxRangeField));
  }
  return ranges;
}

void LevelExtremes::add(const FbaLevels& levels) {
  for (std::size_t i = 0; i < levels.size(); ++i) {
    min[i] = std::min(min[i], levels[i]);
    max[i] = std::max(max[i], levels[i]);
  }
}

bool size_predicted_fields(const LevelExtremes& extremes, const FapMask& mask, int fap_quant,
                           std::array<FbaRangeFields, kFapCount>& ranges) {
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (!mask.test(n)) continue;
    const auto hi = fba_range_field(extremes.max[at(n)], fap_quant);
    const auto lo = fba_range_field(-std::int64_t{extremes.min[at(n)]}, fap_quant);
    if (!hi || !lo) return false;
    ranges[at(n)].p_max = static_cast<std::uint8_t>(*hi);
    ranges[at(n)].p_min = static_cast<std::uint8_t>(*lo);
  }
  return true;
}

// --- planes -------------------------------------------------------------------------------------

void write_plane(FbaCodingState& state, const FapFrame& frame, const IntraHeader* intra, FbaBitWriter& out) {
  out.put_bit(intra != nullptr);
  out.put(kObjectMaskFap, 2);
  if (intra) {
    out.put_bit(1);  // is_frame_rate
    out.put(static_cast<std::uint32_t>(intra->rate.frame_rate), 8);
    out.put(static_cast<std::uint32_t>(intra->rate.seconds), 4);
    out.put_bit(intra->rate.frequency_offset);
    out.put_bit(0);  // is_time_code: timing is the running count of frames
  }
  out.put_bit(0);  // skip_frames: a sequence has no gaps
  if (intra) {
    out.put(static_cast<std::uint32_t>(intra->fap_quant), 5);
    write_group_masks(frame.mask, out);
    out.put_bit(0);  // suggested_gender
    out.put_bit(0);  // coding_type: predictive
    out.put(0b1111, 4);  // is_i_new_max, is_i_new_min, is_p_new_max, is_p_new_min
    auto ranges = intra->ranges;
    for_each_range_field(frame.mask, [&](int flag, int n, bool marker) {
      if (marker) out.put_bit(1);
      out.put(field(ranges[at(n)], flag), 5);
    });
    // fapcast fields (spec/fba.md §4): frame_number, is_predictor, predictor per masked FAP.
    out.put(intra->frame_number, 16);
    std::array<std::uint8_t, kFapCount> predictors = intra->predictors;
    bool any = false;
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
      if (!frame.mask.test(n)) predictors[at(n)] = 0;
      any = any || predictors[at(n)] != 0;
    }
    out.put_bit(any);
    for (int n = kFirstLowLevelFap; n <= kFapCount && any; ++n) {
      if (frame.mask.test(n)) out.put(predictors[at(n)], 5);
    }
    state.rate = intra->rate.rate();
    state.begin_intra(intra->fap_quant, frame.mask, intra->ranges, predictors);
  }
  write_segments(state, frame, intra != nullptr, out);
  ++state.planes;
}

std::error_code read_plane(FbaCodingState& state, FbaBitReader& in, FapFrame& out, PlaneInfo& info) {
  info = PlaneInfo{};
  const auto fail = [&](std::error_code e) {
    state.have_intra = false;
    in.fail(e);  // keeps an earlier error if there was one
    return in.error();
  };
  info.intra = in.get_bit() == 1;
  if (in.get(2) != kObjectMaskFap && !in.error()) in.fail(fba_errc::unsupported_object);
  if (in.error()) return fail(in.error());
  if (!info.intra && !state.have_intra) return fail(fba_errc::predicted_without_intra);
  if (info.intra) {
    if (in.get_bit() == 1) {  // is_frame_rate
      FbaRateFields rate;
      rate.frame_rate = static_cast<int>(in.get(8));
      rate.seconds = static_cast<int>(in.get(4));
      rate.frequency_offset = in.get_bit() == 1;
      if (!in.error() && (rate.frame_rate == 0 || rate.seconds == 0)) in.fail(fba_errc::bad_frame_rate);
      if (!in.error()) state.rate = rate.rate();
    }
    if (in.get_bit() == 1) {  // is_time_code: read and checked; timing counts frames
      in.get(5);
      const std::uint32_t minutes = in.get(6);
      in.marker();
      const std::uint32_t seconds = in.get(6);
      if (!in.error() && (minutes > 59 || seconds > 59)) in.fail(fba_errc::bad_time_code);
    }
  }
  if (in.get_bit() == 1) {  // skip_frames: 4-bit counts, continuing while a count is 15
    std::uint32_t count = 0;
    do {
      count = in.get(4);
      info.skip_frames += static_cast<int>(count);
      if (info.skip_frames > kMaxSkipFrames) in.fail(fba_errc::skip_too_long);
    } while (count == 15 && !in.error());
  }
  if (info.intra) {
    const int fap_quant = static_cast<int>(in.get(5));
    const FapMask mask = read_group_masks(in);
    in.get_bit();  // suggested_gender: no use here
    if (in.get_bit() == 1 && !in.error()) in.fail(fba_errc::dct_coding_unsupported);
    const std::uint32_t flags = in.get(4);
    std::array<FbaRangeFields, kFapCount> ranges{};
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) ranges[at(n)] = fba_default_range_fields(n);
    for_each_range_field(mask, [&](int flag, int n, bool marker) {
      if (!(flags & (0b1000u >> flag))) return;
      if (marker) in.marker();
      field(ranges[at(n)], flag) = static_cast<std::uint8_t>(in.get(5));
    });
    info.frame_number = static_cast<std::uint16_t>(in.get(16));
    std::array<std::uint8_t, kFapCount> predictors{};
    if (in.get_bit() == 1) {
      for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
        if (mask.test(n)) predictors[at(n)] = static_cast<std::uint8_t>(in.get(5));
      }
    }
    if (in.error()) return fail(in.error());
    state.begin_intra(fap_quant, mask, ranges, predictors);
  }
  read_segments(state, info.intra, in, out);
  if (in.past_end()) in.fail(fba_errc::truncated);
  if (in.error()) return fail(in.error());
  ++state.planes;
  return {};
}

std::uint64_t write_unit(FbaCodingState& state, const FapFrame& frame, const IntraHeader* intra,
                         FbaBitWriter& out) {
  const std::uint64_t start = fba_bit_count(out.position());
  out.start_code(kFbaPlaneStartCode);
  write_plane(state, frame, intra, out);
  const std::uint64_t bits = fba_bit_count(out.position()) - start;
  out.align();
  return bits;
}

std::error_code read_unit(FbaCodingState& state, std::span<const std::uint8_t> unit, FapFrame& out,
                          PlaneInfo& info, std::uint64_t& bits, std::uint64_t& error_bit) {
  info = PlaneInfo{};
  bits = 0;
  error_bit = 0;
  // The start code is read as bytes: its 23 zeros are exactly what stuffing keeps out of a plane.
  if (unit.size() < 4 || unit[0] != 0 || unit[1] != 0 || unit[2] != 1 || unit[3] != (kFbaPlaneStartCode & 0xFF)) {
    state.have_intra = false;
    return unit.size() < 4 ? fba_errc::truncated : fba_errc::bad_start_code;
  }
  FbaBitReader in(unit.subspan(4));  // stuffing restarts after the start code
  std::error_code e = read_plane(state, in, out, info);
  bits = fba_bit_count(in.position()) + 32;
  if (!e) {
    in.expect_end();
    e = in.error();
    if (e) state.have_intra = false;
  }
  if (e) error_bit = 32 + in.error_bits();
  return e;
}

}  // namespace fapcast::detail
