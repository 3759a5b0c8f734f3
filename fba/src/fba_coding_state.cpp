#include "fba_coding_state.hpp"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <limits>
#include <cstdlib>

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

FbaRangeFields fba_default_range_fields(int fap) {
  const FapInfo& info = fap_info(fap);
  const auto i = static_cast<std::uint8_t>(info.range_i / kRangeFieldUnit);
  const auto p = static_cast<std::uint8_t>(info.range_p / kRangeFieldUnit);
  return {i, i, p, p};
}

FrameRate FbaRateFields::rate() const {
  const auto fr = static_cast<std::uint32_t>(frame_rate);
  const auto s = static_cast<std::uint32_t>(seconds);
  return frequency_offset ? FrameRate{fr * 1000, s * 1001} : FrameRate{fr, s};
}

std::optional<FbaRateFields> fba_rate_fields(FrameRate rate) {
  if (!rate.valid()) return std::nullopt;
  for (bool offset : {false, true}) {
    for (int seconds = 1; seconds <= 15; ++seconds) {
      // frame_rate = rate * seconds (/ (1000/1001) with the offset), when it is a whole number.
      std::uint64_t num = std::uint64_t{rate.numerator} * static_cast<std::uint64_t>(seconds);
      std::uint64_t den = rate.denominator;
      if (offset) {
        num *= 1001;
        den *= 1000;
      }
      if (num % den != 0) continue;
      const std::uint64_t frame_rate = num / den;
      if (frame_rate >= 1 && frame_rate <= 255) return FbaRateFields{static_cast<int>(frame_rate), seconds, offset};
    }
  }
  return std::nullopt;
}

FbaCodedFaps::FbaCodedFaps(const FapMask& mask, const std::array<FbaRangeFields, kFapCount>& ranges, int fap_quant) {
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap) {
    if (!mask.test(fap)) continue;
    const auto i = static_cast<std::size_t>(fap - 1);
    const FbaRangeFields& r = ranges[i];
    faps_[static_cast<std::size_t>(count_++)] = {static_cast<std::uint8_t>(i), fba_step(fap, fap_quant),
                                                 -fba_range_levels(r.i_min, fap_quant), fba_range_levels(r.i_max, fap_quant),
                                                 -fba_range_levels(r.p_min, fap_quant), fba_range_levels(r.p_max, fap_quant)};
  }
}

namespace {

void reset_models(FbaModels& m, const FapMask& mask, const FbaCodedFaps& coded, bool intra) {
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap) {
    if (!mask.test(fap)) m.fap[static_cast<std::size_t>(fap - 1)] = FrequencyModel{};
  }
  for (const FbaCodedFap& f : coded)
    m.fap[f.index].reset(intra ? f.intra_max - f.intra_min + 1 : f.predicted_max - f.predicted_min + 1);
  m.viseme_select1.reset(15);
  m.viseme_select2.reset(15);
  m.viseme_blend.reset(64);
  m.expression_select1.reset(7);
  m.expression_intensity1.reset(64);
  m.expression_select2.reset(7);
  m.expression_intensity2.reset(64);
}

struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void add(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xFF;
      h *= 1099511628211ull;
    }
  }
  void add(const FrequencyModel& m) {
    add(static_cast<std::uint64_t>(m.size()));
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

void FbaCodingState::begin_intra(int new_fap_quant, const FapMask& new_mask,
                                 const std::array<FbaRangeFields, kFapCount>& new_ranges,
                                 const std::array<std::uint8_t, kFapCount>& new_predictors) {
  have_intra = true;
  prediction.predictor = new_predictors;
  fap_quant = new_fap_quant;
  mask = new_mask;
  ranges = new_ranges;
  for (int fap = 1; fap <= kFapCount; ++fap) {
    if (fap < kFirstLowLevelFap || !mask.test(fap)) {  // carry no meaning
      ranges[static_cast<std::size_t>(fap - 1)] = {};
      prediction.predictor[static_cast<std::size_t>(fap - 1)] = 0;
    }
  }
  coded = FbaCodedFaps(mask, ranges, fap_quant);
  reset_models(intra, mask, coded, true);
  reset_models(predicted, mask, coded, false);
}

std::uint64_t FbaCodingState::checksum() const {
  Fnv f;
  f.add(have_intra);
  f.add(rate.numerator);
  f.add(rate.denominator);
  f.add(static_cast<std::uint64_t>(fap_quant));
  for (int fap = 1; fap <= kFapCount; ++fap) {
    const auto i = static_cast<std::size_t>(fap - 1);
    f.add(mask.test(fap));
    f.add(static_cast<std::uint64_t>(ranges[i].i_max) << 24 | std::uint64_t{ranges[i].i_min} << 16 |
          std::uint64_t{ranges[i].p_max} << 8 | ranges[i].p_min);
    const FbaPrediction& p = prediction;
    f.add(p.predictor[i]);
    for (const std::int32_t r : {p.r1[i], p.r2[i], p.r3[i]}) f.add(static_cast<std::uint64_t>(std::int64_t{r}));
  }
  f.add(std::uint64_t{viseme.select1} << 24 | std::uint64_t{viseme.select2} << 16 | std::uint64_t{viseme.blend} << 8 | viseme.def);
  f.add(std::uint64_t{expression.select1} << 40 | std::uint64_t{expression.intensity1} << 32 |
        std::uint64_t{expression.select2} << 24 | std::uint64_t{expression.intensity2} << 16 |
        std::uint64_t{expression.init_face} << 8 | expression.def);
  f.add(intra);
  f.add(predicted);
  f.add(planes);
  return f.h;
}

}  // namespace fapcast
