#pragma once
// Division of 32-bit numbers by a fixed divisor through one multiplication, exactly (the method
// of Granlund and Montgomery, "Division by invariant integers using multiplication", 1994, in the
// form Lemire et al. describe for 64-bit products). The arithmetic coder divides by a model's
// total, which changes only when the model does, so it keeps the reciprocal with the model.
#include <cstdint>

namespace fapcast {

// m = ceil(2^63 / d). Then floor(n / d) = floor(n * m / 2^63) for every n < 2^32 and
// 1 <= d < 2^31. Proof: m * d = 2^63 + e with 0 <= e < d, so n * m / 2^63 = n / d + n * e /
// (d * 2^63); the added term is below 1 / d because n * e < n * d < 2^63, and the fractional
// part of n / d is at most (d - 1) / d, so the floor does not move.
class ExactReciprocal {
 public:
  static constexpr std::uint32_t kMaxDivisor = (1u << 31) - 1;

  constexpr ExactReciprocal() = default;
  // d: 1..kMaxDivisor.
  constexpr explicit ExactReciprocal(std::uint32_t d) : m_((kTwoTo63 - 1) / d + 1) {}
  // floor(n / d), for any 32-bit n.
  constexpr std::uint32_t divide(std::uint32_t n) const {
    return static_cast<std::uint32_t>((static_cast<Wide>(m_) * n) >> 63);
  }
  constexpr bool operator==(const ExactReciprocal&) const = default;

 private:
  __extension__ typedef unsigned __int128 Wide;  // GCC and Clang: one 64 x 64 -> 128-bit multiply
  static constexpr std::uint64_t kTwoTo63 = std::uint64_t{1} << 63;
  std::uint64_t m_ = kTwoTo63;  // d = 1
};

}  // namespace fapcast
