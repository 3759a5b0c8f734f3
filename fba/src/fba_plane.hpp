#pragma once
// One object plane (one frame) of an FBA stream, written and read by mirrored functions over
// FbaCodingState, in either profile. Internal to the codec: the frame-at-a-time coder and the
// file coder share it. spec/fba.md §3-§7 (standard), §10 (fapcast profile).
#include "fba_bits.hpp"
#include "fba_coding_state.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <system_error>

namespace fapcast::detail {

inline constexpr int kMaxSkipFrames = 255;  // per plane; a decoder refuses more

// Quantisation levels of one frame, index n-1 for FAP n (3..68); 0 where not masked. 64-bit: a
// fapcast-profile P level at fap_quant 0 is the difference of two int32 values.
using FbaLevels = std::array<std::int64_t, kFapCount>;

// The levels of `frame` coded as an intra plane at `fap_quant`.
FbaLevels intra_levels(const FapFrame& frame, int fap_quant);
// The levels of `frame` coded as a P plane: its differences to the predictions.
FbaLevels predicted_levels(const FbaPrediction& prediction, const FbaCodedFaps& faps, const FapFrame& frame);
// One FAP moved on by its level (closed loop: both sides do the same).
inline void reconstruct(FbaPrediction& p, const FbaCodedFap& f, std::int64_t level, bool intra) {
  const std::size_t i = f.index;
  // 64-bit, then saturated: a hostile stream may pile up P steps; an encoder's never do.
  const std::int64_t delta = level * f.step;
  const std::int64_t value = intra ? delta : fba_predict(p.predictor[i], p.r1[i], p.r2[i], p.r3[i]) + delta;
  const auto r = static_cast<std::int32_t>(
      std::clamp<std::int64_t>(value, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()));
  p.r3[i] = intra ? r : p.r2[i];
  p.r2[i] = intra ? r : p.r1[i];
  p.r1[i] = r;
}
void reconstruct(FbaPrediction& prediction, const FbaLevels& levels, const FbaCodedFaps& faps, bool intra);
// Whether `levels` fit the I (or P) range of every coded FAP (standard).
bool levels_fit(const FbaLevels& levels, const FbaCodedFaps& faps, bool intra);

// Checks what the encoder of `profile` cannot code: viseme/expression fields out of their
// ranges, and (standard) values whose intra level no 5-bit range field reaches. On error
// `detail` names frame and FAP.
std::error_code check_codable(FbaProfile profile, const FapFrame& frame, int fap_quant, std::uint64_t frame_index,
                              std::string& detail);

// Standard: range fields sized to intra levels, and P fields sized to the extremes of P levels.
std::array<FbaRangeFields, kFapCount> intra_range_fields(const FbaLevels& levels, const FapMask& mask, int fap_quant);
struct LevelExtremes {
  std::array<std::int64_t, kFapCount> min{}, max{};
  void add(const FbaLevels& levels);
};
// P fields covering `extremes`; false when some FAP needs more than 31.
bool size_predicted_fields(const LevelExtremes& extremes, const FapMask& mask, int fap_quant,
                           std::array<FbaRangeFields, kFapCount>& fields);

// The temporal header of an intra plane.
struct FbaTimeCode {
  int hours = 0, minutes = 0, seconds = 0;  // 0..31, 0..59, 0..59
  bool operator==(const FbaTimeCode&) const = default;
};
// The time code of frame `index` at `rate`: its presentation time truncated to the second
// (hours modulo 32).
FbaTimeCode fba_time_code(std::uint64_t index, FrameRate rate);

// What a standard intra plane's header carries.
struct StandardIntraHeader {
  int fap_quant = 0;
  FbaRateFields rate;
  std::optional<FbaTimeCode> time_code;
  FbaRangeFlags flags;                              // which range fields are sent
  std::array<FbaRangeFields, kFapCount> fields{};   // their values (masked FAPs 3..68)
};
// What a fapcast-profile intra plane's header carries.
struct FapcastIntraHeader {
  int fap_quant = 0;
  FbaRateFields rate;
  std::uint16_t frame_number = 0;  // the frame's index, modulo 65536
  int log2_increment = 3;          // P models count 1 << this per symbol
  std::array<std::uint8_t, kFapCount> predictors{};  // 0..31 per FAP
  // Per masked FAP n (index n-1): reference FAP number (0 none, else an earlier masked FAP),
  // coefficient in sixteenths, and the direct P alphabet [p_min, p_max] in levels.
  std::array<std::uint8_t, kFapCount> reference{};
  std::array<std::int16_t, kFapCount> coefficient{};
  std::array<std::int32_t, kFapCount> p_min{}, p_max{};
};
// The coded-FAP list a fapcast intra header defines for `mask` and `fap_quant`.
FbaCodedFaps fapcast_coded_faps(const FapMask& mask, int fap_quant, const FapcastIntraHeader& header);
inline constexpr int kMaxDirectSymbols = FrequencyModel::kMaxSymbols - 1;  // fapcast: plus the escape

// Model updates a plane owes: the standard encoder codes a plane without counting its symbols
// until the plane is kept (each model codes at most one symbol per plane), so that a plane can
// be taken back.
struct PlaneUpdates {
  std::array<std::pair<FrequencyModel*, int>, kFapCount + 8> pending{};
  int count = 0;
  FbaPrediction prediction;
  VisemeField viseme;
  ExpressionField expression;
};

// Writes one plane's bits (no start code, no stuffing) and moves `state` on exactly as read_plane
// will. Exactly one of `standard`/`fapcast` is given for an intra plane (matching
// state.profile after it), neither for a P plane. `skip_frames`: frames held after this one.
// Preconditions: check_codable passed, and (standard) the levels fit the ranges in force.
// With `updates`, the plane's model counts and reconstruction are left in it for keep_plane()
// (standard only); without, they are applied at once.
void write_plane(FbaCodingState& state, const FapFrame& frame, const StandardIntraHeader* standard,
                 const FapcastIntraHeader* fapcast, int skip_frames, FbaBitWriter& out, PlaneUpdates* updates = nullptr);
// Applies a written plane's updates.
void keep_plane(FbaCodingState& state, const PlaneUpdates& updates);

// What read_plane learnt besides the frame.
struct PlaneInfo {
  bool intra = false;
  int skip_frames = 0;
  bool rate = false;                       // intra planes: the header carried a frame rate
  std::optional<FbaTimeCode> time_code;    // standard intra planes
  std::uint16_t frame_number = 0;          // fapcast intra planes
};

// Reads one plane's bits at the reader's position, in state.profile's syntax (the profile of a
// stream never changes). On error the state is left needing an intra plane; the reader holds the
// error and where it was noticed.
std::error_code read_plane(FbaCodingState& state, FbaBitReader& in, FapFrame& out, PlaneInfo& info);

// Whether the bits of a standard plane, written since `plane` with `carry_zero_run` zeros of the
// same run before it, read alike by a reader of either stuffing reading and by the published
// decoder's fixed give-back of 14 raw bits (spec/fba.md §2). `start_code_follows`: the plane is
// followed by next_start_code() and a start code, else by a P plane.
bool reads_alike(const FbaBitWriter& out, const FbaBitWriter::Mark& plane, int carry_zero_run, bool start_code_follows);
// The zero run a continuous reader carries out of the bits written since `plane`.
int continuous_zero_run(const FbaBitWriter& out, const FbaBitWriter::Mark& plane, int carry_zero_run);

}  // namespace fapcast::detail
