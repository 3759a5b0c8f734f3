#pragma once
// One object plane (one frame) of the FBA stream, written and read by mirrored functions over
// FbaCodingState. Internal to the codec: the frame-at-a-time coder and the file coder share it.
#include "fapcast/codec/fba_bits.hpp"
#include "fapcast/codec/fba_coding_state.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <system_error>

namespace fapcast::codec::detail {

inline constexpr int kMaxSkipFrames = 255;  // per plane; a decoder refuses more

// Quantisation levels of one frame, index n-1 for FAP n (3..68); 0 where not masked.
using FbaLevels = std::array<std::int32_t, kFapCount>;

// The levels of `frame` coded as an intra plane at `fap_quant`.
FbaLevels intra_levels(const FapFrame& frame, int fap_quant);
// The levels of `frame` coded as a P plane: its differences to the reconstructed values.
FbaLevels predicted_levels(const std::array<std::int32_t, kFapCount>& reconstructed, int fap_quant,
                           const FapFrame& frame);
// Moves reconstructed values on by one plane's levels (closed loop: both sides do the same).
void reconstruct(std::array<std::int32_t, kFapCount>& reconstructed, const FbaLevels& levels,
                 const FapMask& mask, int fap_quant, bool intra);
// Whether `levels` fit [-levels(min_field), levels(max_field)] for every masked FAP.
bool levels_fit(const FbaLevels& levels, const FapMask& mask, const FbaCodingState& state, bool intra);

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
  FbaRateFields rate;
};

// Writes one plane, start code to byte alignment, and moves `state` on exactly as
// read_plane will. `intra` is null for a P plane. Preconditions: check_codable passed, and the
// levels fit the ranges in force (the caller chose intra otherwise). Returns the plane's bits
// before byte alignment, start code included (what read_plane reports as PlaneInfo::bits).
std::uint64_t write_plane(FbaCodingState& state, const FapFrame& frame, const IntraHeader* intra,
                          FbaBitWriter& out);

// What read_plane learnt besides the frame.
struct PlaneInfo {
  bool intra = false;
  int skip_frames = 0;
  std::uint64_t bits = 0;       // raw bits consumed before byte alignment (fba_bit_count)
  std::uint64_t error_bit = 0;  // where the error was noticed, bits from the unit start
};

// Reads one plane from `unit` (start code to byte alignment, nothing after). On error the state
// is left needing an intra plane.
std::error_code read_plane(FbaCodingState& state, std::span<const std::uint8_t> unit, FapFrame& out,
                           PlaneInfo& info);

}  // namespace fapcast::codec::detail
