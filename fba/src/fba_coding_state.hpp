#pragma once
// The state an FBA encoder and decoder share and keep in step, plane after plane: the intra
// header in force (fap_quant, mask, coding ranges), the reconstructed values P planes predict
// from, and the adaptive models (intra models reset at every I plane, P models kept until the
// next). Both sides hold one; tests compare them after every frame. The quantiser is public
// (fba_quantiser.hpp).
#include "arithmetic_coder.hpp"
#include "fapcast/fba/fba_quantiser.hpp"
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/core/frame_rate.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <cstdint>
#include <optional>

namespace fapcast {

inline constexpr int kMaxRangeField = 31;    // new-min/max fields are 5 bits
inline constexpr int kRangeFieldUnit = 60;   // range = 60 * field / fap_quant levels

// Levels a range field (0..31) spans at `fap_quant`: 60 * field / max(fap_quant, 1).
int fba_range_levels(int field, int fap_quant);
// The smallest field (0..31) whose range spans `levels` (>= 0) at `fap_quant`, or nullopt.
std::optional<int> fba_range_field(std::int64_t levels, int fap_quant);

// The four 5-bit range fields of one FAP; the range in levels is [-levels(min), levels(max)].
struct FbaRangeFields {
  std::uint8_t i_max = 0, i_min = 0, p_max = 0, p_min = 0;
  bool operator==(const FbaRangeFields&) const = default;
};
// The fields a decoder assumes when an intra header sends none: the FAP table's default ranges.
FbaRangeFields fba_default_range_fields(int fap);

// frame_rate(8) / seconds(4), times 1000/1001 when frequency_offset is set.
struct FbaRateFields {
  int frame_rate = 25;  // 1..255
  int seconds = 1;      // 1..15
  bool frequency_offset = false;
  FrameRate rate() const;
};
// The fields that say `rate` exactly, or nullopt when none do (e.g. 1000/3).
std::optional<FbaRateFields> fba_rate_fields(FrameRate rate);

// fapcast: P prediction (spec/fba.md §6). Predictor 0 is the previous reconstructed value r1
// (the notes' codec). Predictor k = 1..31 is r3 + (k - 7) * (r1 - r2) / 8 over the last three
// reconstructed values r1, r2, r3: exact for a constant plus one sinusoid of w radians per frame
// when (k - 7) / 8 = 1 + 2 cos w, and for any quadratic at k = 31. Computed in 64 bits, rounded
// half up (floor((d * (k - 7) + 4) / 8)), saturated to int32.
inline constexpr int kMaxPredictor = 31;
inline std::int32_t fba_predict(int predictor, std::int32_t r1, std::int32_t r2, std::int32_t r3) {
  if (predictor == 0) return r1;
  const std::int64_t slope = (std::int64_t{r1} - r2) * (predictor - 7);
  const std::int64_t p = std::int64_t{r3} + ((slope + 4) >> 3);  // C++20: >> is arithmetic
  return static_cast<std::int32_t>(
      std::clamp<std::int64_t>(p, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()));
}

// What P levels are predicted from: each FAP's predictor (set by the intra header) and its last
// three reconstructed values (all three equal to the intra value right after an intra plane).
struct FbaPrediction {
  std::array<std::uint8_t, kFapCount> predictor{};  // 0..kMaxPredictor
  std::array<std::int32_t, kFapCount> r1{}, r2{}, r3{};
  bool operator==(const FbaPrediction&) const = default;
};

// A masked low-level FAP as the planes of one intra period code it. Derived from the intra
// header in force (mask, ranges, fap_quant), so that per-plane loops visit only coded FAPs and
// divide nothing. Symbol = level - min of the range in use.
struct FbaCodedFap {
  std::uint8_t index = 0;                             // n - 1 for FAP n (3..68)
  std::int32_t step = 1;                              // fba_step(n, fap_quant), FAPU per level
  std::int32_t intra_min = 0, intra_max = 0;          // the I range, levels: [-levels(i_min), levels(i_max)]
  std::int32_t predicted_min = 0, predicted_max = 0;  // the P range, levels
  bool operator==(const FbaCodedFap&) const = default;
};

// The masked FAPs 3..68 of an intra header, in FAP order (the order planes code them).
class FbaCodedFaps {
 public:
  FbaCodedFaps() = default;
  FbaCodedFaps(const FapMask& mask, const std::array<FbaRangeFields, kFapCount>& ranges, int fap_quant);
  const FbaCodedFap* begin() const { return faps_.data(); }
  const FbaCodedFap* end() const { return faps_.data() + count_; }
  bool empty() const { return count_ == 0; }
  bool operator==(const FbaCodedFaps&) const = default;

 private:
  std::array<FbaCodedFap, kFapCount> faps_{};
  int count_ = 0;
};

// One set of models: one per low-level FAP, and the viseme and expression fields.
struct FbaModels {
  std::array<FrequencyModel, kFapCount> fap;  // fap[n-1] for FAP n (3..68)
  FrequencyModel viseme_select1, viseme_select2, viseme_blend;
  FrequencyModel expression_select1, expression_intensity1, expression_select2, expression_intensity2;
  bool operator==(const FbaModels&) const = default;
};

struct FbaCodingState {
  bool have_intra = false;  // false until an intra plane, and again after an error
  FrameRate rate;           // from the last intra plane that carried one
  int fap_quant = 0;
  FapMask mask;
  std::array<FbaRangeFields, kFapCount> ranges{};
  FbaCodedFaps coded;        // mask, ranges and fap_quant as the planes use them
  FbaPrediction prediction;  // prediction.r1: what the decoder shows, FAPU
  VisemeField viseme;
  ExpressionField expression;
  FbaModels intra, predicted;
  std::uint64_t planes = 0;  // planes coded since the state was made

  // Starts an intra period: the header fields in force, all models uniform over their ranges.
  void begin_intra(int new_fap_quant, const FapMask& new_mask,
                   const std::array<FbaRangeFields, kFapCount>& new_ranges,
                   const std::array<std::uint8_t, kFapCount>& new_predictors);
  // FNV-1a over everything above: a cheap end-of-stream check that two sides agree.
  std::uint64_t checksum() const;
  bool operator==(const FbaCodingState&) const = default;
};

}  // namespace fapcast
