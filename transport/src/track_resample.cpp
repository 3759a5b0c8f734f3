#include "fapcast/transport/track_resample.hpp"

#include "fapcast/codec/fap_table.hpp"

#include <cmath>

namespace fapcast::transport {
namespace {
__extension__ typedef __int128 Int128;

// round(a + (b - a) * num / den), half away from zero, in exact integer arithmetic.
std::int32_t lerp_rounded(std::int32_t a, std::int32_t b, std::int64_t num, std::int64_t den) {
  const Int128 scaled = static_cast<Int128>(a) * den + static_cast<Int128>(b - std::int64_t{a}) * num;
  const Int128 half = den / 2;
  const Int128 q = scaled >= 0 ? (scaled + half) / den : -((-scaled + half) / den);
  return static_cast<std::int32_t>(q);
}
}  // namespace

SourcePosition source_position(std::int64_t j, codec::FrameRate from, codec::FrameRate to) {
  // t_j = j * to.den / to.num seconds; source index = t_j * from.num / from.den.
  const Int128 num = static_cast<Int128>(j) * to.denominator * from.numerator;
  const Int128 den = static_cast<Int128>(to.numerator) * from.denominator;
  return {static_cast<std::int64_t>(num / den), static_cast<std::int64_t>(num % den),
          static_cast<std::int64_t>(den)};
}

std::int64_t resampled_frame_count(std::int64_t n, codec::FrameRate from, codec::FrameRate to) {
  const Int128 num = static_cast<Int128>(n) * to.numerator * from.denominator;
  const Int128 den = static_cast<Int128>(to.denominator) * from.numerator;
  return static_cast<std::int64_t>((num + den - 1) / den);
}

codec::FapSequence resample_track(const codec::FapSequence& seq, codec::FrameRate to,
                                  ResampleMode mode) {
  codec::FapSequence out;
  out.name = seq.name;
  out.rate = to;
  const auto n = static_cast<std::int64_t>(seq.frames.size());
  const std::int64_t count = resampled_frame_count(n, seq.rate, to);
  out.frames.reserve(static_cast<std::size_t>(count));
  for (std::int64_t j = 0; j < count; ++j) {
    const SourcePosition p = source_position(j, seq.rate, to);
    const std::int64_t k = p.index < n ? p.index : n - 1;
    codec::FapFrame frame = seq.frames[static_cast<std::size_t>(k)];
    if (mode == ResampleMode::kLinear && p.remainder != 0 && k + 1 < n) {
      const codec::FapFrame& next = seq.frames[static_cast<std::size_t>(k + 1)];
      for (int fap = 3; fap <= codec::kFapCount; ++fap)
        if (frame.mask.test(fap) && next.mask.test(fap))
          frame.values[static_cast<std::size_t>(fap - 1)] =
              lerp_rounded(frame.value(fap), next.value(fap), p.remainder, p.denominator);
    }
    out.frames.push_back(frame);
  }
  return out;
}

}  // namespace fapcast::transport
