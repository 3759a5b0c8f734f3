#include "fapcast/core/frame_rate.hpp"

namespace fapcast {
namespace {
__extension__ typedef __int128 Int128;  // GCC and clang both have it
}  // namespace

std::ostream& operator<<(std::ostream& out, FrameRate rate) {
  out << rate.numerator;
  if (rate.denominator != 1) out << '/' << rate.denominator;
  return out << " fps";
}

// 128-bit intermediates: an hour at 192 kHz and 1001-denominators stays far from overflow.
std::int64_t frame_to_sample(std::int64_t k, FrameRate rate, SampleRate sample_rate) {
  const Int128 num = static_cast<Int128>(k) * sample_rate.hz * rate.denominator;
  const Int128 den = rate.numerator;
  return static_cast<std::int64_t>((2 * num + den) / (2 * den));
}

std::int64_t sample_to_frame(std::int64_t sample, FrameRate rate, SampleRate sample_rate) {
  // Estimate by floor, then correct for the rounding in frame_to_sample.
  const Int128 num = static_cast<Int128>(sample) * rate.numerator;
  const Int128 den = static_cast<Int128>(sample_rate.hz) * rate.denominator;
  std::int64_t k = static_cast<std::int64_t>(num / den);
  while (k > 0 && frame_to_sample(k, rate, sample_rate) > sample) --k;
  while (frame_to_sample(k + 1, rate, sample_rate) <= sample) ++k;
  return k;
}

std::int64_t first_frame_at(std::int64_t sample, FrameRate rate, SampleRate sample_rate) {
  // frame_to_sample(k) = floor((2 k R d + n) / 2n) >= s  <=>  2 k R d >= 2 n s - n.
  const Int128 need = static_cast<Int128>(2) * rate.numerator * sample - rate.numerator;
  if (need <= 0) return 0;
  const Int128 step = static_cast<Int128>(2) * sample_rate.hz * rate.denominator;
  return static_cast<std::int64_t>((need + step - 1) / step);
}

}  // namespace fapcast
