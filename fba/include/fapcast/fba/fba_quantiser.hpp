#pragma once
// The FBA quantiser (spec/fba.md): the step of each low-level FAP at a fap_quant, and the level
// a value quantises to. What an encoder loses and what a decoder reconstructs (level x step).
#include <cstdint>

namespace fapcast {

inline constexpr int kMaxFapQuant = 31;      // fap_quant is 5 bits; 0 = lossless

// Quantiser step of FAP `fap` (3..68) at `fap_quant` (0..31): QP * fap_quant, 1 when lossless.
int fba_step(int fap, int fap_quant);
// Quantisation level of `value` (FAPU) at `step` (>= 1): 0 within step/2, else rounded away.
std::int64_t fba_quantise(std::int64_t value, int step);

}  // namespace fapcast
