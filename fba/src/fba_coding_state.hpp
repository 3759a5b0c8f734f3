#pragma once
// The state an FBA encoder and decoder share and keep in step, plane after plane: the profile,
// the intra header in force (fap_quant, mask, coding ranges), the reconstructed values P planes
// predict from, and the adaptive models (reset at every intra plane). Both sides hold one; tests
// compare them after every frame. The range and rate fields live here too; the quantiser is
// public (fba_quantiser.hpp). spec/fba.md: §4 (ranges), §6 (quantisation), §10 (prediction).
#include "arithmetic_coder.hpp"
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/core/frame_rate.hpp"
#include "fapcast/fba/fba_profile.hpp"
#include "fapcast/fba/fba_quantiser.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>

namespace fapcast {

inline constexpr int kMaxRangeField = 31;    // new-min/max fields are 5 bits
inline constexpr int kRangeFieldUnit = 60;   // range = 60 * field / fap_quant levels

// Levels a range field (0..31) spans at `fap_quant`: 60 * field / max(fap_quant, 1).
int fba_range_levels(int field, int fap_quant);
// The smallest field (0..31) whose range spans `levels` (>= 0) at `fap_quant`, or nullopt.
std::optional<int> fba_range_field(std::int64_t levels, int fap_quant);

// A FAP's coding ranges in levels: I values in [i_min, i_max], P differences in [p_min, p_max]
// (min <= 0 <= max).
struct FbaRangeLevels {
  std::int32_t i_min = 0, i_max = 0, p_min = 0, p_max = 0;
  bool operator==(const FbaRangeLevels&) const = default;
};
// The standard's defaults at the first intra plane: the FAP table's range rounded up to a whole
// field (60 units), in levels at `fap_quant` (FAP 63's 680 becomes 720, as the published decoder).
FbaRangeLevels fba_default_range_levels(int fap, int fap_quant);
// The four 5-bit fields of an intra header that set a FAP's ranges; a field absent (the flag not
// set) leaves the range in force.
struct FbaRangeFields {
  std::uint8_t i_max = 0, i_min = 0, p_max = 0, p_min = 0;
  bool operator==(const FbaRangeFields&) const = default;
};
// Which of is_i_new_max, is_i_new_min, is_p_new_max, is_p_new_min an intra header sets.
struct FbaRangeFlags {
  bool i_max = false, i_min = false, p_max = false, p_min = false;
  bool any() const { return i_max || i_min || p_max || p_min; }
  bool operator==(const FbaRangeFlags&) const = default;
};
// Viseme blend and expression intensities are quantised by fap_quant: their largest level.
// 63 at fap_quant 0 and 1, (63 + fap_quant / 2) / fap_quant otherwise.
int fba_blend_levels(int fap_quant);

// frame_rate(8) + seconds(4)/16, times 1000/1001 when frequency_offset is set.
struct FbaRateFields {
  int frame_rate = 25;  // 0..255
  int seconds = 0;      // 0..15: sixteenths of a frame per second
  bool frequency_offset = false;
  FrameRate rate() const;  // invalid (numerator 0) for 0 + 0/16
  bool operator==(const FbaRateFields&) const = default;
};
// The fields that say `rate` exactly, or nullopt when none do (e.g. 10/3).
std::optional<FbaRateFields> fba_rate_fields(FrameRate rate);

// fapcast profile: P prediction (spec/fba.md §10). Predictor 0 is the previous reconstructed
// value r1 (the standard's). Predictor k = 1..31 is r3 + (k - 7) * (r1 - r2) / 8 over the last three
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
// fapcast profile: the part of a FAP's P level its reference FAP predicts, round(c * e / 16) for
// the reference's level e of the same frame and the coefficient c in sixteenths (64-bit, half up).
inline std::int64_t fba_reference_part(std::int32_t coefficient, std::int64_t reference_level) {
  return (coefficient * reference_level + 8) >> 4;
}

// What P levels are predicted from: each FAP's predictor (set by the intra header) and its last
// three reconstructed values (all three equal to the intra value right after an intra plane).
struct FbaPrediction {
  std::array<std::uint8_t, kFapCount> predictor{};  // 0..kMaxPredictor; always 0 in the standard
  std::array<std::int32_t, kFapCount> r1{}, r2{}, r3{};
  bool operator==(const FbaPrediction&) const = default;
};

// A masked low-level FAP as the planes of one intra period code it, derived from the intra
// header in force, so that per-plane loops visit only coded FAPs and divide nothing.
struct FbaCodedFap {
  std::uint8_t index = 0;   // n - 1 for FAP n (3..68)
  std::int32_t step = 1;    // fba_step(n, fap_quant), FAPU per level
  std::int32_t intra_min = 0, intra_max = 0;          // the I range, levels (standard)
  std::int32_t predicted_min = 0, predicted_max = 0;  // the P range, levels (fapcast: the direct alphabet)
  std::int8_t reference = -1;  // fapcast: position of the reference FAP in this list (earlier), -1 none
  std::int16_t coefficient = 0;  // fapcast: in sixteenths
  bool operator==(const FbaCodedFap&) const = default;
};

// The masked FAPs 3..68 of an intra header, in FAP order (the order planes code them).
class FbaCodedFaps {
 public:
  FbaCodedFaps() = default;
  FbaCodedFaps(const FapMask& mask, const std::array<FbaRangeLevels, kFapCount>& ranges, int fap_quant);
  const FbaCodedFap* begin() const { return faps_.data(); }
  const FbaCodedFap* end() const { return faps_.data() + count_; }
  FbaCodedFap* begin() { return faps_.data(); }
  FbaCodedFap* end() { return faps_.data() + count_; }
  int size() const { return count_; }
  bool empty() const { return count_ == 0; }
  const FbaCodedFap& operator[](int i) const { return faps_[static_cast<std::size_t>(i)]; }
  FbaCodedFap& operator[](int i) { return faps_[static_cast<std::size_t>(i)]; }
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
  FbaProfile profile = FbaProfile::kStandard;
  bool have_intra = false;  // false until an intra plane, and again after an error
  bool rate_known = false;  // an intra plane carried frame-rate fields
  FrameRate rate;           // from the last intra plane that carried one (25 fps until then)
  int fap_quant = 0;
  FapMask mask;
  // The ranges in force, levels, every low-level FAP. Standard: they persist from intra plane to
  // intra plane; the defaults are set while FAP 4's I range is 0..0 (never set, or set so).
  std::array<FbaRangeLevels, kFapCount> ranges{};
  int blend_levels = 63;  // viseme blend and intensities: I 0..this, P +/- this (standard: kept at q 0)
  FbaCodedFaps coded;        // mask, ranges and fap_quant as the planes use them
  FbaPrediction prediction;  // prediction.r1: what the decoder shows, FAPU
  VisemeField viseme;        // the last reconstructed FAP 1 and FAP 2 fields (blend and
  ExpressionField expression;  // intensities on the quantiser's grid, up to 75)
  FbaModels intra, predicted;
  FrequencyModel escape_bits;  // fapcast: bit length of an escaped P level (41 symbols: 0..40)
  int increment = 1;           // P models' count increment (fapcast: 1 << log2_increment)
  std::array<std::int64_t, kFapCount> levels{};  // fapcast: this frame's P levels, by coded position
  std::uint64_t planes = 0;  // planes coded since the state was made

  // Standard: an intra header's fap_quant, mask and range fields applied to the ranges in force
  // (the published decoder's rules, spec/fba.md §4), and the models reset.
  void begin_standard_intra(int new_fap_quant, const FapMask& new_mask, const FbaRangeFlags& flags,
                            const std::array<FbaRangeFields, kFapCount>& fields);
  // fapcast: an intra header's fap_quant, mask, increment and per-FAP P alphabet, predictors and
  // references (already in `faps`, built by the caller over `new_mask`).
  void begin_fapcast_intra(int new_fap_quant, const FapMask& new_mask, int log2_increment,
                           const FbaCodedFaps& faps, const std::array<std::uint8_t, kFapCount>& predictors);
  // FNV-1a over everything above: a cheap end-of-stream check that two sides agree.
  std::uint64_t checksum() const;
  bool operator==(const FbaCodingState&) const = default;

 private:
  void reset_models();
};

}  // namespace fapcast
