#include "fba_coding_state.hpp"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <limits>
#include <numeric>

namespace fapcast {

int fba_range_levels(int field, int fap_quant) {
  return kRangeFieldUnit * field / (fap_quant == 0 ? 1 : fap_quant);
}

std::optional<int> fba_range_field(std::int64_t levels, int fap_quant) {
  for (int field = 0; field <= kMaxRangeField; ++field) {
    if (fba_range_levels(field, fap_quant) >= levels) return field;
  }
  return std::nullopt;
}

FbaRangeLevels fba_default_range_levels(int fap, int fap_quant) {
  const FapInfo& info = fap_info(fap);
  const int i = fba_range_levels((info.range_i + kRangeFieldUnit - 1) / kRangeFieldUnit, fap_quant);
  const int p = fba_range_levels((info.range_p + kRangeFieldUnit - 1) / kRangeFieldUnit, fap_quant);
  return {-i, i, -p, p};
}

int fba_blend_levels(int fap_quant) {
  return fap_quant <= 1 ? 63 : (63 + fap_quant / 2) / fap_quant;
}

FrameRate FbaRateFields::rate() const {
  const auto sixteenths = static_cast<std::uint32_t>(16 * frame_rate + seconds);
  const std::uint32_t num = frequency_offset ? sixteenths * 1000 : sixteenths;
  const std::uint32_t den = frequency_offset ? 16 * 1001 : 16;
  const std::uint32_t g = std::gcd(num, den);
  return g == 0 ? FrameRate{0, 1} : FrameRate{num / g, den / g};
}

std::optional<FbaRateFields> fba_rate_fields(FrameRate rate) {
  if (!rate.valid()) return std::nullopt;
  for (bool offset : {false, true}) {
    // sixteenths = rate * 16 (* 1001/1000 with the offset), when it is a whole number 1..4095.
    std::uint64_t num = std::uint64_t{rate.numerator} * 16;
    std::uint64_t den = rate.denominator;
    if (offset) {
      num *= 1001;
      den *= 1000;
    }
    if (num % den != 0) continue;
    const std::uint64_t sixteenths = num / den;
    if (sixteenths >= 1 && sixteenths <= 16 * 255 + 15)
      return FbaRateFields{static_cast<int>(sixteenths / 16), static_cast<int>(sixteenths % 16), offset};
  }
  return std::nullopt;
}

FbaCodedFaps::FbaCodedFaps(const FapMask& mask, const std::array<FbaRangeLevels, kFapCount>& ranges, int fap_quant) {
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap) {
    if (!mask.test(fap)) continue;
    const auto i = fap_slot(fap);
    const FbaRangeLevels& r = ranges[i];
    FbaCodedFap& f = faps_[static_cast<std::size_t>(count_++)];
    f.index = static_cast<std::uint8_t>(i);
    f.step = fba_step(fap, fap_quant);
    f.intra_min = r.i_min;
    f.intra_max = r.i_max;
    f.predicted_min = r.p_min;
    f.predicted_max = r.p_max;
  }
}

void FbaCodingState::reset_models() {
  const bool escape = profile == FbaProfile::kFapcast;
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap) {
    if (!mask.test(fap)) {
      intra.fap[fap_slot(fap)] = FrequencyModel{};
      predicted.fap[fap_slot(fap)] = FrequencyModel{};
    }
  }
  for (const FbaCodedFap& f : coded) {
    if (!escape) intra.fap[f.index].reset(f.intra_max - f.intra_min + 1);
    predicted.fap[f.index].reset(f.predicted_max - f.predicted_min + 1 + (escape ? 1 : 0), increment);
  }
  const int blend = blend_levels;
  intra.viseme_select1.reset(15);
  intra.viseme_select2.reset(15);
  intra.viseme_blend.reset(blend + 1);
  intra.expression_select1.reset(7);
  intra.expression_intensity1.reset(blend + 1);
  intra.expression_select2.reset(7);
  intra.expression_intensity2.reset(blend + 1);
  predicted.viseme_select1.reset(29, increment);
  predicted.viseme_select2.reset(29, increment);
  predicted.viseme_blend.reset(2 * blend + 1, increment);
  predicted.expression_select1.reset(13, increment);
  predicted.expression_intensity1.reset(2 * blend + 1, increment);
  predicted.expression_select2.reset(13, increment);
  predicted.expression_intensity2.reset(2 * blend + 1, increment);
  if (escape) {
    escape_bits.reset(41, increment);
  } else {
    escape_bits = FrequencyModel{};
  }
  levels = {};
}

void FbaCodingState::begin_standard_intra(int new_fap_quant, const FapMask& new_mask, const FbaRangeFlags& flags,
                                          const std::array<FbaRangeFields, kFapCount>& fields) {
  profile = FbaProfile::kStandard;
  have_intra = true;
  fap_quant = new_fap_quant;
  mask = new_mask;
  increment = 1;
  // The published decoder sets every range to its default while FAP 4's I range is 0..0.
  const FbaRangeLevels& fap4 = ranges[3];
  if (fap4.i_min == 0 && fap4.i_max == 0) {
    for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap)
      ranges[fap_slot(fap)] = fba_default_range_levels(fap, fap_quant);
  }
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap) {
    if (!mask.test(fap)) continue;
    const auto i = fap_slot(fap);
    FbaRangeLevels& r = ranges[i];
    const FbaRangeFields& f = fields[i];
    if (flags.i_max) r.i_max = fba_range_levels(f.i_max, fap_quant);
    if (flags.i_min) r.i_min = -fba_range_levels(f.i_min, fap_quant);
    if (flags.p_max) r.p_max = fba_range_levels(f.p_max, fap_quant);
    if (flags.p_min) r.p_min = -fba_range_levels(f.p_min, fap_quant);
  }
  if (fap_quant != 0) blend_levels = fba_blend_levels(fap_quant);  // kept at 0, as the published decoder
  prediction.predictor = {};
  coded = FbaCodedFaps(mask, ranges, fap_quant);
  reset_models();
}

void FbaCodingState::begin_fapcast_intra(int new_fap_quant, const FapMask& new_mask, int log2_increment,
                                         const FbaCodedFaps& faps,
                                         const std::array<std::uint8_t, kFapCount>& predictors) {
  profile = FbaProfile::kFapcast;
  have_intra = true;
  fap_quant = new_fap_quant;
  mask = new_mask;
  increment = 1 << log2_increment;
  blend_levels = fba_blend_levels(fap_quant);
  coded = faps;
  ranges = {};
  for (const FbaCodedFap& f : coded) ranges[f.index] = {0, 0, f.predicted_min, f.predicted_max};
  prediction.predictor = {};
  for (const FbaCodedFap& f : coded) prediction.predictor[f.index] = predictors[f.index];
  reset_models();
}

namespace {

struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void add(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xFF;
      h *= 1099511628211ull;
    }
  }
  void add_signed(std::int64_t v) { add(static_cast<std::uint64_t>(v)); }
  void add(const FrequencyModel& m) {
    add(static_cast<std::uint64_t>(m.size()) << 8 | static_cast<std::uint64_t>(m.increment()));
    for (int i = 0; i <= m.size() && m.size() > 0; ++i) add(m.cumulative(i));  // size 0: an unused model
  }
  void add(const FbaModels& m) {
    for (const auto& f : m.fap) add(f);
    for (const auto* f : {&m.viseme_select1, &m.viseme_select2, &m.viseme_blend, &m.expression_select1,
                          &m.expression_intensity1, &m.expression_select2, &m.expression_intensity2})
      add(*f);
  }
};

}  // namespace

std::uint64_t FbaCodingState::checksum() const {
  Fnv f;
  f.add(static_cast<std::uint64_t>(profile));
  f.add(have_intra);
  f.add(rate_known);
  f.add(rate.numerator);
  f.add(rate.denominator);
  f.add(static_cast<std::uint64_t>(fap_quant));
  f.add_signed(blend_levels);
  f.add_signed(increment);
  for (int fap = 1; fap <= kFapCount; ++fap) {
    const auto i = fap_slot(fap);
    f.add(mask.test(fap));
    for (const std::int32_t r : {ranges[i].i_min, ranges[i].i_max, ranges[i].p_min, ranges[i].p_max}) f.add_signed(r);
    const FbaPrediction& p = prediction;
    f.add(p.predictor[i]);
    for (const std::int32_t r : {p.r1[i], p.r2[i], p.r3[i]}) f.add_signed(r);
  }
  for (const FbaCodedFap& c : coded) f.add_signed(std::int64_t{c.reference} << 32 | static_cast<std::uint16_t>(c.coefficient));
  f.add(std::uint64_t{viseme.select1} << 24 | std::uint64_t{viseme.select2} << 16 | std::uint64_t{viseme.blend} << 8 | viseme.def);
  f.add(std::uint64_t{expression.select1} << 40 | std::uint64_t{expression.intensity1} << 32 |
        std::uint64_t{expression.select2} << 24 | std::uint64_t{expression.intensity2} << 16 |
        std::uint64_t{expression.init_face} << 8 | expression.def);
  f.add(intra);
  f.add(predicted);
  f.add(escape_bits);
  f.add(planes);
  return f.h;
}

}  // namespace fapcast
