#include "fba_plane.hpp"

#include "fapcast/fba/fba_errc.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <sstream>

namespace fapcast::detail {
namespace {

constexpr int kObjectMaskFap = 1;  // fba_object_mask: 1 = FAP (2 = body, 3 = both: not implemented)
enum MaskType : std::uint32_t { kMaskNone = 0, kMaskBits = 1, kMaskBitsAlt = 2, kMaskAll = 3 };
constexpr int kMarkerEvery = 4;  // a marker bit before group positions 0, 4, 8, 12 of the range fields
constexpr int kSelect1Levels = 14, kExpressionSelectLevels = 6;
constexpr int kMaxReferenceCoefficient = 64;  // fapcast: |c| <= 4 (in sixteenths)
// fapcast: a level is at most the difference of two int32 values (fap_quant 0, any predictor).
constexpr std::int64_t kMaxLevel = std::int64_t{1} << 33;

// --- group masks ----------------------------------------------------------------------------------

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

// --- standard range fields --------------------------------------------------------------------------

// Visits the range fields of the flags set, in order (i_max, i_min, p_max, p_min): for every FAP
// of groups 2..10, a marker before group positions 0, 4, 8, 12, then the field if it is masked.
template <typename Marker, typename Field>
void for_each_range_field(const FapMask& mask, const FbaRangeFlags& flags, Marker&& marker, Field&& field) {
  const bool set[4] = {flags.i_max, flags.i_min, flags.p_max, flags.p_min};
  for (int flag = 0; flag < 4; ++flag) {
    if (!set[flag]) continue;
    for (int g = 2; g <= kGroupCount; ++g) {
      const FapRange faps = fap_group(g);
      for (int n = faps.first; n <= faps.last; ++n) {
        if ((n - faps.first) % kMarkerEvery == 0) marker();
        if (mask.test(n)) field(flag, n);
      }
    }
  }
}

std::uint8_t& field_of(FbaRangeFields& r, int flag) {
  switch (flag) {
    case 0: return r.i_max;
    case 1: return r.i_min;
    case 2: return r.p_max;
    default: return r.p_min;
  }
}

// --- Exp-Golomb fields (fapcast profile headers) -----------------------------------------------------

void put_ue(FbaBitWriter& out, std::uint64_t v) {
  const std::uint64_t x = v + 1;
  const int bits = std::bit_width(x);
  for (int i = 1; i < bits; ++i) out.put_bit(0);
  for (int i = bits - 1; i >= 0; --i) out.put_bit(static_cast<int>((x >> i) & 1u));
}
void put_se(FbaBitWriter& out, std::int64_t v) {
  put_ue(out, v > 0 ? 2 * static_cast<std::uint64_t>(v) - 1 : 2 * static_cast<std::uint64_t>(-v));
}
// Values above 2^40 are refused (bad-field): no field of the profile needs more.
std::uint64_t get_ue(FbaBitReader& in) {
  int zeros = 0;
  while (in.get_bit() == 0 && !in.error()) {
    if (++zeros > 40) {
      in.fail(fba_errc::bad_field);
      return 0;
    }
  }
  std::uint64_t x = 1;
  for (int i = 0; i < zeros; ++i) x = (x << 1) | static_cast<std::uint64_t>(in.get_bit());
  return in.error() ? 0 : x - 1;
}
std::int64_t get_se(FbaBitReader& in) {
  const std::uint64_t u = get_ue(in);
  return u % 2 == 1 ? static_cast<std::int64_t>((u + 1) / 2) : -static_cast<std::int64_t>(u / 2);
}

// --- symbols ------------------------------------------------------------------------------------------

// Codes symbols into one segment, counting them in their models at once or later (PlaneUpdates).
class SymbolWriter {
 public:
  SymbolWriter(FbaBitWriter& out, PlaneUpdates* updates) : ac_(out), updates_(updates) {}
  void code(int s, FrequencyModel& m) {
    if (updates_) {
      ac_.encode_only(s, m);
      updates_->pending[static_cast<std::size_t>(updates_->count++)] = {&m, s};
    } else {
      ac_.encode(s, m);
    }
  }
  void code_uncounted(int s, const FrequencyModel& m) { ac_.encode_only(s, m); }
  void flush() { ac_.flush(); }

 private:
  ArithmeticEncoder ac_;
  PlaneUpdates* updates_;
};

// The largest viseme blend or expression intensity the state's coding can give.
int fap12_max(const FbaCodingState& s) { return std::max(63, s.blend_levels * std::max(s.fap_quant, 1)); }

// FAP 1 and FAP 2: intra planes code the fields, P planes their differences (spec/fba.md §5).
void write_fap12(const FbaCodingState& s, const FapFrame& frame, bool intra, FbaBitWriter& out,
                 PlaneUpdates* updates, VisemeField& viseme, ExpressionField& expression) {
  const FbaModels& const_models = intra ? s.intra : s.predicted;
  FbaModels& m = const_cast<FbaModels&>(const_models);  // counted through SymbolWriter only
  const int step = std::max(s.fap_quant, 1);
  const int blend = s.blend_levels;
  // A quantised field: the level coded and the field reconstructed from it.
  const auto quantised = [&](int value, int previous, int& reconstructed) {
    const auto level = static_cast<int>(fba_quantise(intra ? value : value - previous, step));  // |level| <= 75
    reconstructed = (intra ? 0 : previous) + level * step;
    return level + (intra ? 0 : blend);
  };
  if (frame.mask.test(kVisemeFap)) {
    SymbolWriter w(out, intra ? nullptr : updates);
    const VisemeField& v = frame.viseme;
    const VisemeField& p = s.viseme;
    int b = 0;
    const int blend_symbol = quantised(v.blend, p.blend, b);
    if (intra) {
      w.code_uncounted(v.select1, m.viseme_select1);
      w.code_uncounted(v.select2, m.viseme_select2);
      w.code_uncounted(blend_symbol, m.viseme_blend);
    } else {
      w.code(v.select1 - p.select1 + kSelect1Levels, m.viseme_select1);
      w.code(v.select2 - p.select2 + kSelect1Levels, m.viseme_select2);
      w.code(blend_symbol, m.viseme_blend);
    }
    w.flush();
    out.put_bit(v.def);
    viseme = {v.select1, v.select2, static_cast<std::uint8_t>(b), v.def};
  }
  if (frame.mask.test(kExpressionFap)) {
    SymbolWriter w(out, intra ? nullptr : updates);
    const ExpressionField& e = frame.expression;
    const ExpressionField& p = s.expression;
    int i1 = 0, i2 = 0;
    const int s1 = quantised(e.intensity1, p.intensity1, i1);
    const int s2 = quantised(e.intensity2, p.intensity2, i2);
    if (intra) {
      w.code_uncounted(e.select1, m.expression_select1);
      w.code_uncounted(s1, m.expression_intensity1);
      w.code_uncounted(e.select2, m.expression_select2);
      w.code_uncounted(s2, m.expression_intensity2);
    } else {
      w.code(e.select1 - p.select1 + kExpressionSelectLevels, m.expression_select1);
      w.code(s1, m.expression_intensity1);
      w.code(e.select2 - p.select2 + kExpressionSelectLevels, m.expression_select2);
      w.code(s2, m.expression_intensity2);
    }
    w.flush();
    out.put_bit(e.init_face);
    out.put_bit(e.def);
    expression = {e.select1, static_cast<std::uint8_t>(i1), e.select2, static_cast<std::uint8_t>(i2), e.init_face, e.def};
  }
}

void read_fap12(FbaCodingState& s, bool intra, FbaBitReader& in, FapFrame& out) {
  FbaModels& m = intra ? s.intra : s.predicted;
  const int step = std::max(s.fap_quant, 1);
  const int blend = s.blend_levels;
  const int top = fap12_max(s);
  // Symbol to field: intra planes carry it, P planes the difference; out of 0..limit is the
  // stream's error, never clamped.
  const auto field = [&](int symbol, int offset, int previous, int scale, int limit, fba_errc rule) {
    const int value = (intra ? 0 : previous) + (symbol - (intra ? 0 : offset)) * scale;
    if ((value < 0 || value > limit) && !in.error()) in.fail(rule);
    return static_cast<std::uint8_t>(std::clamp(value, 0, 255));
  };
  const auto decode = [&](ArithmeticDecoder& ad, FrequencyModel& model) { return intra ? ad.decode_only(model) : ad.decode(model); };
  if (s.mask.test(kVisemeFap)) {
    ArithmeticDecoder ad(in);
    const VisemeField p = s.viseme;
    VisemeField& v = out.viseme;
    v.select1 = field(decode(ad, m.viseme_select1), kSelect1Levels, p.select1, 1, kSelect1Levels, fba_errc::viseme_range);
    v.select2 = field(decode(ad, m.viseme_select2), kSelect1Levels, p.select2, 1, kSelect1Levels, fba_errc::viseme_range);
    v.blend = field(decode(ad, m.viseme_blend), blend, p.blend, step, top, fba_errc::viseme_range);
    ad.finish();
    v.def = in.get_bit() == 1;
    s.viseme = v;
  }
  if (s.mask.test(kExpressionFap)) {
    ArithmeticDecoder ad(in);
    const ExpressionField p = s.expression;
    ExpressionField& e = out.expression;
    e.select1 = field(decode(ad, m.expression_select1), kExpressionSelectLevels, p.select1, 1, kExpressionSelectLevels,
                      fba_errc::expression_range);
    e.intensity1 = field(decode(ad, m.expression_intensity1), blend, p.intensity1, step, top, fba_errc::expression_range);
    e.select2 = field(decode(ad, m.expression_select2), kExpressionSelectLevels, p.select2, 1, kExpressionSelectLevels,
                      fba_errc::expression_range);
    e.intensity2 = field(decode(ad, m.expression_intensity2), blend, p.intensity2, step, top, fba_errc::expression_range);
    ad.finish();
    e.init_face = in.get_bit() == 1;
    e.def = in.get_bit() == 1;
    s.expression = e;
  }
}

// --- temporal header ----------------------------------------------------------------------------------

void write_rate(const FbaRateFields& r, FbaBitWriter& out) {
  out.put(static_cast<std::uint32_t>(r.frame_rate), 8);
  out.put(static_cast<std::uint32_t>(r.seconds), 4);
  out.put_bit(r.frequency_offset);
}

bool read_rate(FbaCodingState& s, FbaBitReader& in) {
  FbaRateFields r;
  r.frame_rate = static_cast<int>(in.get(8));
  r.seconds = static_cast<int>(in.get(4));
  r.frequency_offset = in.get_bit() == 1;
  if (in.error()) return false;
  if (r.frame_rate == 0 && r.seconds == 0) {
    in.fail(fba_errc::bad_frame_rate);
    return false;
  }
  s.rate = r.rate();
  s.rate_known = true;
  return true;
}

void write_skip(int skip_frames, FbaBitWriter& out) {
  out.put_bit(skip_frames > 0);
  if (skip_frames == 0) return;
  for (int left = skip_frames;; left -= 15) {
    const int count = std::min(left, 15);
    out.put(static_cast<std::uint32_t>(count), 4);
    if (count < 15) break;
    if (left == 15) {  // 15 exactly: a count of 15 continues, so a 0 ends it
      out.put(0, 4);
      break;
    }
  }
}

void read_skip(FbaBitReader& in, PlaneInfo& info) {
  if (in.get_bit() != 1) return;
  std::uint32_t count = 0;
  do {
    count = in.get(4);
    info.skip_frames += static_cast<int>(count);
    if (info.skip_frames > kMaxSkipFrames) in.fail(fba_errc::skip_too_long);
  } while (count == 15 && !in.error());
}

// --- standard planes ----------------------------------------------------------------------------------

void write_standard_intra_header(FbaCodingState& state, const FapFrame& frame, const StandardIntraHeader& h,
                                 FbaBitWriter& out) {
  out.put(static_cast<std::uint32_t>(h.fap_quant), 5);
  write_group_masks(frame.mask, out);
  out.put_bit(0);  // suggested_gender
  out.put_bit(0);  // coding_type: predictive
  out.put_bit(h.flags.i_max);
  out.put_bit(h.flags.i_min);
  out.put_bit(h.flags.p_max);
  out.put_bit(h.flags.p_min);
  auto fields = h.fields;
  for_each_range_field(frame.mask, h.flags, [&] { out.put_bit(1); },
                       [&](int flag, int n) { out.put(field_of(fields[fap_slot(n)], flag), 5); });
  state.begin_standard_intra(h.fap_quant, frame.mask, h.flags, h.fields);
}

bool read_standard_intra_header(FbaCodingState& state, FbaBitReader& in) {
  const int fap_quant = static_cast<int>(in.get(5));
  const FapMask mask = read_group_masks(in);
  in.get_bit();  // suggested_gender: no use here
  if (in.get_bit() == 1 && !in.error()) in.fail(fba_errc::dct_coding_unsupported);
  FbaRangeFlags flags;
  flags.i_max = in.get_bit() == 1;
  flags.i_min = in.get_bit() == 1;
  flags.p_max = in.get_bit() == 1;
  flags.p_min = in.get_bit() == 1;
  std::array<FbaRangeFields, kFapCount> fields{};
  for_each_range_field(mask, flags, [&] { in.marker(); },
                       [&](int flag, int n) { field_of(fields[fap_slot(n)], flag) = static_cast<std::uint8_t>(in.get(5)); });
  if (in.error()) return false;
  state.begin_standard_intra(fap_quant, mask, flags, fields);
  return true;
}

void write_standard_low_level(const FbaCodingState& s, const FapFrame& frame, bool intra, FbaBitWriter& out,
                              PlaneUpdates* updates, FbaPrediction& prediction) {
  if (s.coded.empty()) return;
  const FbaLevels levels = intra ? intra_levels(frame, s.fap_quant) : predicted_levels(s.prediction, s.coded, frame);
  FbaModels& m = const_cast<FbaModels&>(intra ? s.intra : s.predicted);  // counted through SymbolWriter only
  SymbolWriter w(out, intra ? nullptr : updates);
  for (const FbaCodedFap& f : s.coded) {
    if (intra) {
      w.code_uncounted(static_cast<int>(levels[f.index] - f.intra_min), m.fap[f.index]);
    } else {
      w.code(static_cast<int>(levels[f.index] - f.predicted_min), m.fap[f.index]);
    }
  }
  w.flush();
  reconstruct(prediction, levels, s.coded, intra);
}

void read_standard_low_level(FbaCodingState& s, bool intra, FbaBitReader& in, FapFrame& out) {
  if (s.coded.empty()) return;
  ArithmeticDecoder ad(in);
  if (intra) {
    for (const FbaCodedFap& f : s.coded) {
      reconstruct(s.prediction, f, ad.decode_only(s.intra.fap[f.index]) + f.intra_min, true);
      out.values[f.index] = s.prediction.r1[f.index];
    }
  } else {
    for (const FbaCodedFap& f : s.coded) {
      reconstruct(s.prediction, f, ad.decode(s.predicted.fap[f.index]) + f.predicted_min, false);
      out.values[f.index] = s.prediction.r1[f.index];
    }
  }
  ad.finish();
}

// --- fapcast planes -------------------------------------------------------------------------------------

void write_fapcast_intra_header(FbaCodingState& state, const FapFrame& frame, const FapcastIntraHeader& h,
                                FbaBitWriter& out, FbaPrediction& prediction) {
  out.put(static_cast<std::uint32_t>(h.fap_quant), 5);
  write_group_masks(frame.mask, out);
  out.put(static_cast<std::uint32_t>(h.log2_increment), 3);
  const FbaLevels levels = intra_levels(frame, h.fap_quant);
  const FbaCodedFaps faps = fapcast_coded_faps(frame.mask, h.fap_quant, h);
  for (int k = 0; k < faps.size(); ++k) {
    const FbaCodedFap& f = faps[k];
    put_se(out, levels[f.index]);
    out.put(h.predictors[f.index], 5);
    put_ue(out, f.reference < 0 ? 0 : static_cast<std::uint64_t>(k - f.reference));
    if (f.reference >= 0) put_se(out, f.coefficient);
    put_ue(out, static_cast<std::uint64_t>(-std::int64_t{f.predicted_min}));
    put_ue(out, static_cast<std::uint64_t>(f.predicted_max));
  }
  state.begin_fapcast_intra(h.fap_quant, frame.mask, h.log2_increment, faps, h.predictors);
  prediction = state.prediction;
  reconstruct(prediction, levels, state.coded, true);
}

bool read_fapcast_intra_header(FbaCodingState& state, FbaBitReader& in, FapFrame& out) {
  const int fap_quant = static_cast<int>(in.get(5));
  const FapMask mask = read_group_masks(in);
  const int log2_increment = static_cast<int>(in.get(3));
  if (log2_increment > 6 && !in.error()) in.fail(fba_errc::bad_field);
  FbaCodedFaps faps(mask, {}, fap_quant);
  std::array<std::uint8_t, kFapCount> predictors{};
  FbaLevels levels{};
  for (int k = 0; k < faps.size() && !in.error(); ++k) {
    FbaCodedFap& f = faps[k];
    const std::int64_t level = get_se(in);
    predictors[f.index] = static_cast<std::uint8_t>(in.get(5));
    const std::uint64_t distance = get_ue(in);
    std::int64_t coefficient = 0;
    if (distance > 0) coefficient = get_se(in);
    const std::uint64_t p_min = get_ue(in), p_max = get_ue(in);
    if (in.error()) break;
    if (level < std::numeric_limits<std::int32_t>::min() || level > std::numeric_limits<std::int32_t>::max() ||
        distance > static_cast<std::uint64_t>(k) || coefficient < -kMaxReferenceCoefficient ||
        coefficient > kMaxReferenceCoefficient || p_min + p_max + 1 > static_cast<std::uint64_t>(kMaxDirectSymbols)) {
      in.fail(fba_errc::bad_field);
      break;
    }
    levels[f.index] = level;
    f.reference = distance == 0 ? std::int8_t{-1} : static_cast<std::int8_t>(k - static_cast<int>(distance));
    f.coefficient = static_cast<std::int16_t>(coefficient);
    f.predicted_min = -static_cast<std::int32_t>(p_min);
    f.predicted_max = static_cast<std::int32_t>(p_max);
  }
  if (in.error()) return false;
  state.begin_fapcast_intra(fap_quant, mask, log2_increment, faps, predictors);
  for (const FbaCodedFap& f : state.coded) {
    reconstruct(state.prediction, f, levels[f.index], true);
    out.values[f.index] = state.prediction.r1[f.index];
  }
  return true;
}

const FrequencyModel& uniform_bit() {
  static const FrequencyModel bit(2);
  return bit;
}

void write_escaped(ArithmeticEncoder& ac, FbaCodingState& s, std::int64_t v) {
  const std::uint64_t magnitude = v < 0 ? static_cast<std::uint64_t>(-v) : static_cast<std::uint64_t>(v);
  const int length = std::bit_width(magnitude);  // >= 1: 0 is always a direct symbol
  ac.encode(length, s.escape_bits);
  for (int i = length - 2; i >= 0; --i) ac.encode_only(static_cast<int>((magnitude >> i) & 1u), uniform_bit());
  ac.encode_only(v < 0, uniform_bit());
}

std::int64_t read_escaped(ArithmeticDecoder& ad, FbaCodingState& s) {
  const FrequencyModel& bit = uniform_bit();
  const int length = ad.decode(s.escape_bits);
  if (length == 0 || length > 40) return std::numeric_limits<std::int64_t>::max();  // no encoder writes it
  std::uint64_t magnitude = 1;
  for (int i = length - 2; i >= 0; --i) magnitude = (magnitude << 1) | static_cast<std::uint64_t>(ad.decode_only(bit));
  const bool negative = ad.decode_only(bit) == 1;
  return negative ? -static_cast<std::int64_t>(magnitude) : static_cast<std::int64_t>(magnitude);
}

void write_fapcast_low_level(FbaCodingState& s, const FapFrame& frame, FbaBitWriter& out) {
  if (s.coded.empty()) return;
  const FbaLevels levels = predicted_levels(s.prediction, s.coded, frame);
  ArithmeticEncoder ac(out);
  for (int k = 0; k < s.coded.size(); ++k) {
    const FbaCodedFap& f = s.coded[k];
    const std::int64_t e = levels[f.index];
    const std::int64_t symbol = e - (f.reference < 0 ? 0 : fba_reference_part(f.coefficient, s.levels[static_cast<std::size_t>(f.reference)]));
    FrequencyModel& m = s.predicted.fap[f.index];
    if (symbol >= f.predicted_min && symbol <= f.predicted_max) {
      ac.encode(static_cast<int>(symbol - f.predicted_min), m);
    } else {
      ac.encode(f.predicted_max - f.predicted_min + 1, m);  // the escape symbol
      write_escaped(ac, s, symbol);
    }
    s.levels[static_cast<std::size_t>(k)] = e;
    reconstruct(s.prediction, f, e, false);
  }
  ac.flush();
}

void read_fapcast_low_level(FbaCodingState& s, FbaBitReader& in, FapFrame& out) {
  if (s.coded.empty()) return;
  ArithmeticDecoder ad(in);
  for (int k = 0; k < s.coded.size(); ++k) {
    const FbaCodedFap& f = s.coded[k];
    const int direct = f.predicted_max - f.predicted_min + 1;
    const int symbol = ad.decode(s.predicted.fap[f.index]);
    const std::int64_t value = symbol < direct ? std::int64_t{symbol} + f.predicted_min : read_escaped(ad, s);
    if (value < -kMaxLevel || value > kMaxLevel) {  // checked before the sum: an escape can claim 2^63 - 1
      in.fail(fba_errc::bad_field);
      break;
    }
    const std::int64_t e = value + (f.reference < 0 ? 0 : fba_reference_part(f.coefficient, s.levels[static_cast<std::size_t>(f.reference)]));
    if (e < -kMaxLevel || e > kMaxLevel) {
      in.fail(fba_errc::bad_field);  // no level of an encoder's
      break;
    }
    s.levels[static_cast<std::size_t>(k)] = e;
    reconstruct(s.prediction, f, e, false);
    out.values[f.index] = s.prediction.r1[f.index];
  }
  ad.finish();
}

}  // namespace

// --- quantisation and ranges --------------------------------------------------------------------

FbaLevels intra_levels(const FapFrame& frame, int fap_quant) {
  FbaLevels levels{};
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (frame.mask.test(n)) levels[fap_slot(n)] = fba_quantise(frame.values[fap_slot(n)], fba_step(n, fap_quant));
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
    const std::int64_t level = levels[f.index];
    if (level < (intra ? f.intra_min : f.predicted_min) || level > (intra ? f.intra_max : f.predicted_max)) return false;
  }
  return true;
}

std::error_code check_codable(FbaProfile profile, const FapFrame& frame, int fap_quant, std::uint64_t frame_index,
                              std::string& detail) {
  std::ostringstream msg;
  msg << "frame " << frame_index << ", ";
  const auto refuse = [&](const std::string& what) {
    msg << what << " (refused, never clipped)";
    detail = msg.str();
    return make_error_code(fba_errc::uncodable_value);
  };
  // Blend and intensities: 0..63, or up to the top of fap_quant's grid (64 at 2, 65 at 5: what
  // a standard stream decodes to).
  const int weight = std::max(63, fba_blend_levels(fap_quant) * std::max(fap_quant, 1));
  const std::string weights = "0.." + std::to_string(weight);
  if (frame.mask.test(kVisemeFap)) {
    const VisemeField& v = frame.viseme;
    if (v.select1 > 14 || v.select2 > 14 || v.blend > weight)
      return refuse("FAP 1 viseme: select1/select2 must be 0..14 and blend " + weights + " at fap_quant " +
                    std::to_string(fap_quant));
  }
  if (frame.mask.test(kExpressionFap)) {
    const ExpressionField& e = frame.expression;
    if (e.select1 > 6 || e.select2 > 6 || e.intensity1 > weight || e.intensity2 > weight)
      return refuse("FAP 2 expression: selects must be 0..6 and intensities " + weights + " at fap_quant " +
                    std::to_string(fap_quant));
  }
  if (profile == FbaProfile::kFapcast) return {};  // every int32 value is codable there
  const int max_levels = fba_range_levels(kMaxRangeField, fap_quant);
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (!frame.mask.test(n)) continue;
    const int step = fba_step(n, fap_quant);
    const std::int64_t level = fba_quantise(frame.values[fap_slot(n)], step);
    if (level > max_levels || level < -max_levels) {
      msg << "FAP " << n << " " << fap_info(n).name << ": value " << frame.values[fap_slot(n)]
          << " is beyond the standard syntax's codable range +/-" << std::int64_t{max_levels} * step << " at fap_quant "
          << fap_quant;
      return refuse("");
    }
  }
  return {};
}

std::array<FbaRangeFields, kFapCount> intra_range_fields(const FbaLevels& levels, const FapMask& mask, int fap_quant) {
  std::array<FbaRangeFields, kFapCount> ranges{};
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (!mask.test(n)) continue;
    const std::int64_t level = levels[fap_slot(n)];
    ranges[fap_slot(n)].i_max = static_cast<std::uint8_t>(fba_range_field(std::max<std::int64_t>(level, 0), fap_quant).value_or(kMaxRangeField));
    ranges[fap_slot(n)].i_min = static_cast<std::uint8_t>(fba_range_field(std::max<std::int64_t>(-level, 0), fap_quant).value_or(kMaxRangeField));
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
                           std::array<FbaRangeFields, kFapCount>& fields) {
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (!mask.test(n)) continue;
    const auto hi = fba_range_field(extremes.max[fap_slot(n)], fap_quant);
    const auto lo = fba_range_field(-extremes.min[fap_slot(n)], fap_quant);
    if (!hi || !lo) return false;
    fields[fap_slot(n)].p_max = static_cast<std::uint8_t>(*hi);
    fields[fap_slot(n)].p_min = static_cast<std::uint8_t>(*lo);
  }
  return true;
}

FbaTimeCode fba_time_code(std::uint64_t index, FrameRate rate) {
  const std::uint64_t seconds = index * rate.denominator / rate.numerator;
  return {static_cast<int>(seconds / 3600 % 32), static_cast<int>(seconds / 60 % 60), static_cast<int>(seconds % 60)};
}

FbaCodedFaps fapcast_coded_faps(const FapMask& mask, int fap_quant, const FapcastIntraHeader& h) {
  FbaCodedFaps faps(mask, {}, fap_quant);
  std::array<int, kFapCount + 1> position{};  // FAP number -> position in the list
  for (int k = 0; k < faps.size(); ++k) position[static_cast<std::size_t>(faps[k].index + 1)] = k;
  for (FbaCodedFap& f : faps) {
    const int reference = h.reference[f.index];
    f.reference = reference == 0 ? std::int8_t{-1} : static_cast<std::int8_t>(position[static_cast<std::size_t>(reference)]);
    f.coefficient = reference == 0 ? std::int16_t{0} : h.coefficient[f.index];
    f.predicted_min = h.p_min[f.index];
    f.predicted_max = h.p_max[f.index];
  }
  return faps;
}

// --- planes -------------------------------------------------------------------------------------

void write_plane(FbaCodingState& state, const FapFrame& frame, const StandardIntraHeader* standard,
                 const FapcastIntraHeader* fapcast, int skip_frames, FbaBitWriter& out, PlaneUpdates* updates) {
  const bool intra = standard || fapcast;
  const bool profile_fapcast = fapcast || (!standard && state.profile == FbaProfile::kFapcast);
  PlaneUpdates local;
  PlaneUpdates& u = updates ? *updates : local;
  u.count = 0;
  out.put_bit(intra);
  if (!profile_fapcast) out.put(kObjectMaskFap, 2);
  if (intra) {
    if (standard) {
      out.put_bit(1);  // is_frame_rate
      write_rate(standard->rate, out);
      out.put_bit(standard->time_code.has_value());
      if (standard->time_code) {
        out.put(static_cast<std::uint32_t>(standard->time_code->hours), 5);
        out.put(static_cast<std::uint32_t>(standard->time_code->minutes), 6);
        out.put_bit(1);  // marker
        out.put(static_cast<std::uint32_t>(standard->time_code->seconds), 6);
      }
    } else {
      write_rate(fapcast->rate, out);
      out.put(fapcast->frame_number, 16);
    }
  }
  write_skip(skip_frames, out);
  u.prediction = state.prediction;
  if (standard) {
    write_standard_intra_header(state, frame, *standard, out);
    state.rate = standard->rate.rate();
    state.rate_known = true;
    u.prediction = state.prediction;
  } else if (fapcast) {
    state.rate = fapcast->rate.rate();
    state.rate_known = true;
    u.prediction = state.prediction;
    write_fapcast_intra_header(state, frame, *fapcast, out, u.prediction);
  }
  u.viseme = state.viseme;
  u.expression = state.expression;
  write_fap12(state, frame, intra, out, &u, u.viseme, u.expression);
  if (!profile_fapcast) {
    write_standard_low_level(state, frame, intra, out, &u, u.prediction);
  } else if (!intra) {
    state.prediction = u.prediction;
    write_fapcast_low_level(state, frame, out);
    u.prediction = state.prediction;
  }
  if (!updates) keep_plane(state, u);
}

void keep_plane(FbaCodingState& state, const PlaneUpdates& u) {
  for (int i = 0; i < u.count; ++i) u.pending[static_cast<std::size_t>(i)].first->update(u.pending[static_cast<std::size_t>(i)].second);
  state.prediction = u.prediction;
  state.viseme = u.viseme;
  state.expression = u.expression;
  ++state.planes;
}

std::error_code read_plane(FbaCodingState& state, FbaBitReader& in, FapFrame& out, PlaneInfo& info) {
  info = PlaneInfo{};
  const auto fail = [&](std::error_code e) {
    state.have_intra = false;
    in.fail(e);  // keeps an earlier error if there was one
    return in.error();
  };
  const bool fapcast = state.profile == FbaProfile::kFapcast;
  info.intra = in.get_bit() == 1;
  if (!fapcast) {
    if (in.get(2) != kObjectMaskFap && !in.error()) in.fail(fba_errc::unsupported_object);
  }
  if (in.error()) return fail(in.error());
  if (!info.intra && !state.have_intra) return fail(fba_errc::predicted_without_intra);
  if (info.intra) {
    if (fapcast) {
      info.rate = read_rate(state, in);
      info.frame_number = static_cast<std::uint16_t>(in.get(16));
    } else {
      if (in.get_bit() == 1) info.rate = read_rate(state, in);  // is_frame_rate
      if (in.get_bit() == 1) {                                  // is_time_code
        FbaTimeCode t;
        t.hours = static_cast<int>(in.get(5));
        t.minutes = static_cast<int>(in.get(6));
        in.marker();
        t.seconds = static_cast<int>(in.get(6));
        if (!in.error() && (t.minutes > 59 || t.seconds > 59)) in.fail(fba_errc::bad_time_code);
        info.time_code = t;
      }
    }
  }
  read_skip(in, info);
  if (in.error()) return fail(in.error());
  out = FapFrame{};
  if (info.intra) {
    const bool ok = fapcast ? read_fapcast_intra_header(state, in, out) : read_standard_intra_header(state, in);
    if (!ok) return fail(in.error());
  }
  out.mask = state.mask;
  read_fap12(state, info.intra, in, out);
  if (!fapcast) {
    read_standard_low_level(state, info.intra, in, out);
  } else if (!info.intra) {
    read_fapcast_low_level(state, in, out);
  }
  if (in.past_end()) in.fail(fba_errc::truncated);
  if (in.error()) return fail(in.error());
  ++state.planes;
  return {};
}

// --- reading alike ------------------------------------------------------------------------------

namespace {

// The raw bits of the writer, and what follows them for a reader looking ahead: a P plane's
// first bits (0, 0, 1: is_intra, fba_object_mask) or next_start_code() and a start code.
class Continued {
 public:
  Continued(const FbaBitWriter& out, bool start_code_follows)
      : bytes_(out.bytes()), end_(out.position().raw_bits), start_code_(start_code_follows) {
    if (start_code_) {
      stuffing_ = 1 + static_cast<int>((8 - (end_ + 1) % 8) % 8);  // a 0, then 1s to the boundary
    }
  }
  // Bit `p`, or -1 where it is not known (a P plane's bits after its first three).
  int bit(std::uint64_t p) const {
    if (p < end_) return (bytes_[p / 8] >> (7 - p % 8)) & 1;
    const std::uint64_t k = p - end_;
    if (!start_code_) return k < 2 ? 0 : k == 2 ? 1 : -1;
    if (k < static_cast<std::uint64_t>(stuffing_)) return k == 0 ? 0 : 1;
    const std::uint64_t c = k - static_cast<std::uint64_t>(stuffing_);  // into 00 00 01 xx
    return c < 23 ? 0 : c == 23 ? 1 : -1;
  }

 private:
  const std::vector<std::uint8_t>& bytes_;
  std::uint64_t end_;
  bool start_code_;
  int stuffing_ = 0;
};

// The continuous reader over [begin, end): false when it would stuff where the writer did not,
// or not where it did. `run`: the zeros before, then after.
bool continuous_agrees(const FbaBitWriter& out, std::uint64_t begin, int& run) {
  const Continued bits(out, false);
  const std::vector<std::uint64_t>& stuffed = out.stuffed_bits();
  std::size_t k = 0;
  for (std::uint64_t p = begin; p < out.position().raw_bits; ++p) {
    const bool is_stuffed = k < stuffed.size() && stuffed[k] == p;
    if (run == kStuffAfterZeros) {
      if (!is_stuffed) return false;
      ++k;
      run = 0;
      continue;
    }
    if (is_stuffed) return false;
    run = bits.bit(p) ? 0 : run + 1;
  }
  return true;
}

}  // namespace

int continuous_zero_run(const FbaBitWriter& out, const FbaBitWriter::Mark& plane, int carry_zero_run) {
  int run = carry_zero_run;
  continuous_agrees(out, plane.pos.raw_bits, run);
  return run;
}

bool reads_alike(const FbaBitWriter& out, const FbaBitWriter::Mark& plane, int carry_zero_run, bool start_code_follows) {
  int run = carry_zero_run;
  if (!continuous_agrees(out, plane.pos.raw_bits, run)) return false;
  // A continuous reader stuffs right after a 22nd zero, and a P plane starts with two zeros.
  if (run >= kStuffAfterZeros - (start_code_follows ? 0 : 2)) return false;
  // The published decoder: at each segment end it has read 14 payload bits beyond the encoder's,
  // counting zeros from the segment's start, and gives back 14 raw bits: wrong if it met (or
  // thought it met) a stuffed bit in them.
  const Continued bits(out, start_code_follows);
  for (const FbaSegmentSpan& s : out.segments()) {
    int zeros = 0;
    for (std::uint64_t p = s.end; p > s.begin && bits.bit(p - 1) == 0; --p) ++zeros;
    std::uint64_t p = s.end;
    for (int i = 0; i < 14; ++i, ++p) {
      if (zeros == kStuffAfterZeros) return false;
      const int b = bits.bit(p);
      if (b < 0) break;  // a P plane's header has a 1 among its first bits: no 22 zeros from here
      zeros = b ? 0 : zeros + 1;
    }
  }
  return true;
}

}  // namespace fapcast::detail
