#pragma once
// One object plane (one frame) of the FBA stream, written and read by mirrored functions over
// FbaCodingState. Internal to the codec: the frame-at-a-time coder and the file coder share it.
#include "fba_bits.hpp"
#include "fba_coding_state.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <system_error>

namespace fapcast::detail {

inline constexpr int kMaxSkipFrames = 255;  // per plane; a decoder refuses more

// Quantisation levels of one frame, index n-1 for FAP n (3..68); 0 where not masked.
using FbaLevels = std::array<std::int32_t, kFapCount>;

// The levels of `frame` coded as an intra plane at `fap_quant`.
FbaLevels intra_levels(const FapFrame& frame, int fap_quant);
// The levels of `frame` coded as a P plane: its differences to the predictions.
FbaLevels predicted_levels(const FbaPrediction& prediction, const FbaCodedFaps& faps, const FapFrame& frame);
// Moves the reconstructed values on by one plane's levels (closed loop: both sides do the same),
// or one FAP's.
void reconstruct(FbaPrediction& prediction, const FbaLevels& levels, const FbaCodedFaps& faps, bool intra);
inline void reconstruct(FbaPrediction& p, const FbaCodedFap& f, std::int32_t level, bool intra) {
  const std::size_t i = f.index;
  // 64-bit, then saturated: a hostile stream may pile up P steps; an encoder's never do.
  const std::int64_t delta = std::int64_t{level} * f.step;
  const std::int64_t value = intra ? delta : fba_predict(p.predictor[i], p.r1[i], p.r2[i], p.r3[i]) + delta;
  const auto r = static_cast<std::int32_t>(
      std::clamp<std::int64_t>(value, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()));
  p.r3[i] = intra ? r : p.r2[i];
  p.r2[i] = intra ? r : p.r1[i];
  p.r1[i] = r;
}
// Whether `levels` fit the I (or P) range of every coded FAP.
bool levels_fit(const FbaLevels& levels, const FbaCodedFaps& faps, bool intra);

// Checks what the encoder cannot code: viseme/expression fields out of their ranges, and values
// whose intra level no 5-bit range field reaches. On error `detail` names frame and FAP.
std::error_code check_codable(const FapFrame& frame, int fap_quant, std::uint64_t frame_index,
                              std::string& detail);

// Range fields sized to intra levels, and P range fields sized to the extremes of P levels.
std::array<FbaRangeFields, kFapCount> intra_range_fields(const FbaLevels& levels, const FapMask& mask,
                                                         int fap_quant);
struct LevelExtremes {
  std::array<std::int32_t, kFapCount> min{}, max{};
  void add(const FbaLevels& levels);
};
// P fields covering `extremes`; false when some FAP needs more than 31.
bool size_predicted_fields(const LevelExtremes& extremes, const FapMask& mask, int fap_quant,
                           std::array<FbaRangeFields, kFapCount>& ranges);

// What an intra plane's header carries.
struct IntraHeader {
  int fap_quant = 0;
  std::array<FbaRangeFields, kFapCount> ranges{};
  std::array<std::uint8_t, kFapCount> predictors{};  // all 0: is_predictor 0, none sent
  std::uint16_t frame_number = 0;                     // the frame's index, modulo 65536
  FbaRateFields rate;
};

// Writes one plane's bits (no start code, no alignment) and moves `state` on exactly as
// read_plane will. `intra` is null for a P plane. Preconditions: check_codable passed, and the
// levels fit the ranges in force (the caller chose intra otherwise).
void write_plane(FbaCodingState& state, const FapFrame& frame, const IntraHeader* intra, FbaBitWriter& out);

// What read_plane learnt besides the frame.
struct PlaneInfo {
  bool intra = false;
  int skip_frames = 0;
  std::uint16_t frame_number = 0;  // intra planes only
};

// Reads one plane's bits at the reader's position. On error the state is left needing an
// intra plane; the reader holds the error and where it was noticed.
std::error_code read_plane(FbaCodingState& state, FbaBitReader& in, FapFrame& out, PlaneInfo& info);

// A unit of the frame-at-a-time coder: plane start code, one plane, alignment. Returns the bits
// before alignment, start code included (fba_bit_count, as read_unit reports).
std::uint64_t write_unit(FbaCodingState& state, const FapFrame& frame, const IntraHeader* intra,
                         FbaBitWriter& out);
// Reads a unit (start code, one plane, alignment, nothing after). `bits`: as write_unit's;
// `error_bit`: where an error was noticed, bits from the unit start.
std::error_code read_unit(FbaCodingState& state, std::span<const std::uint8_t> unit, FapFrame& out,
                          PlaneInfo& info, std::uint64_t& bits, std::uint64_t& error_bit);

}  // namespace fapcast::detail
