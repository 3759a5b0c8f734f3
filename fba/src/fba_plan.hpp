#pragma once
// What an encoder decides at each intra plane, from the frames the intra period will hold:
// the standard syntax's range fields (send them or keep the ranges in force, sized to the data:
// spec/fba.md §8) and the fapcast profile's predictors, references and P alphabets (§10).
// Internal to the codec.
#include "fba_plane.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace fapcast::detail {

// log2(x) in 1/256 bit for x >= 1, interpolated linearly between powers of two (at most 0.09
// bit low; integers only, so every platform chooses alike).
std::int64_t log2_q8(std::uint64_t x);

// About the bits an adaptive model over `size` symbols (count increment `increment`, no halving)
// spends on `symbols`, in 1/256 bit; stops counting past `enough`.
std::int64_t adaptive_cost(std::span<const std::int32_t> symbols, std::int32_t offset, int size, int increment,
                           std::int64_t enough = std::numeric_limits<std::int64_t>::max());

// Standard: the intra header for frames[k] heading the period [k, end) (end <= nominal_end: cut
// before a P level no 5-bit field reaches, or a mask change), given the ranges the decoder holds
// (`state`, before the header). Each of the four flags is sent when sending it is cheaper than
// keeping the ranges in force (or when they do not cover the levels). At a `resync_point` (after a
// start code) a decoder may enter with no ranges in force: ranges are kept only where they are
// the defaults a fresh decoder sets.
struct StandardPlan {
  StandardIntraHeader header;
  std::size_t end = 0;
};
StandardPlan plan_standard_period(std::span<const FapFrame> frames, std::size_t k, std::size_t nominal_end,
                                  const FbaCodingState& state, int fap_quant, bool resync_point);

// fapcast: the intra header for frames[k] heading [k, end), frames after k being what the P
// planes will code (for the frame-at-a-time coder: earlier frames standing in for them).
FapcastIntraHeader plan_fapcast_period(std::span<const FapFrame> frames, std::size_t k, std::size_t end, int fap_quant,
                                       bool choose);

}  // namespace fapcast::detail
