#include "fapcast/transport/track_resample.hpp"

#include "fapcast/codec/fap_table.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>
#include <algorithm>

namespace fapcast {
namespace {
__extension__ typedef __int128 Int128;

// round(a + (b - a) * num / den), half away from zero (0 <= num < den): the exact numerator in
// Int, and `floor_quotient(n)` = floor(n / den) for the non-negative numerators it is given.
template <class Int, class FloorQuotient>
std::int32_t lerp_rounded(std::int32_t a, std::int32_t b, std::int64_t num, std::int64_t den,
                          FloorQuotient floor_quotient) {
  const Int scaled = static_cast<Int>(a) * den + static_cast<Int>(b - std::int64_t{a}) * num;
  const Int half = den / 2;
  return static_cast<std::int32_t>(scaled >= 0 ? floor_quotient(scaled + half) : -floor_quotient(-scaled + half));
}

// The same in exact integer arithmetic.
template <class Int>
std::int32_t lerp_rounded(std::int32_t a, std::int32_t b, std::int64_t num, std::int64_t den) {
  return lerp_rounded<Int>(a, b, num, den, [den](Int n) { return n / den; });
}

// Up to this denominator the lerp fits 64 bits: |a| den <= 2^61, |b - a| num < 2^62, so the sum
// and the half stay below 2^63, and the division is one machine instruction instead of a 128-bit
// library call.
constexpr std::int64_t kMaxDenominator64 = std::int64_t{1} << 30;

// Up to this one (every rate pair of practice: 30000/1001 from 60 is 30,000) the numerators below
// are under 2^53 (|a| den <= 2^51, |b - a| num < 2^52, half < 2^19), so they and den are exact as
// doubles, and the correctly rounded quotient N / den of two such non-negative integers is never
// pushed across an integer (its error, under 2^-53 N / den, is below the 1 / den that separates a
// non-integer quotient from the next integer): truncating it is floor(N / den) exactly, and a
// floating-point division is several times cheaper than an integer one.
constexpr std::int64_t kMaxDenominatorDouble = std::int64_t{1} << 20;

std::int32_t lerp_rounded_double(std::int32_t a, std::int32_t b, std::int64_t num, std::int64_t den, double den_d) {
  return lerp_rounded<std::int64_t>(a, b, num, den, [den_d](std::int64_t n) {  // 0 <= n < 2^53
    return static_cast<std::int64_t>(static_cast<double>(n) / den_d);
  });
}

// The low-level FAPs (3..68) masked in both of two frames, listed once per pair of masks.
class CommonFaps {
 public:
  std::span<const int> of(const FapMask& a, const FapMask& b) {
    if (count_ < 0 || !(a == a_) || !(b == b_)) {
      a_ = a;
      b_ = b;
      count_ = 0;
      for (int fap = 3; fap <= kFapCount; ++fap)
        if (a.test(fap) && b.test(fap)) faps_[static_cast<std::size_t>(count_++)] = fap;
    }
    return {faps_.data(), static_cast<std::size_t>(count_)};
  }

 private:
  FapMask a_, b_;
  std::array<int, kFapCount> faps_{};
  int count_ = -1;
};
}  // namespace

SourcePosition source_position(std::int64_t j, FrameRate from, FrameRate to) {
  // t_j = j * to.den / to.num seconds; source index = t_j * from.num / from.den.
  const Int128 num = static_cast<Int128>(j) * to.denominator * from.numerator;
  const Int128 den = static_cast<Int128>(to.numerator) * from.denominator;
  constexpr Int128 kMax64 = std::numeric_limits<std::int64_t>::max();
  if (num >= 0 && num <= kMax64 && den <= kMax64) {  // one machine division, not a library call
    const auto n = static_cast<std::int64_t>(num), d = static_cast<std::int64_t>(den);
    return {n / d, n % d, d};
  }
  return {static_cast<std::int64_t>(num / den), static_cast<std::int64_t>(num % den),
          static_cast<std::int64_t>(den)};
}

std::int64_t resampled_frame_count(std::int64_t n, FrameRate from, FrameRate to) {
  const Int128 num = static_cast<Int128>(n) * to.numerator * from.denominator;
  const Int128 den = static_cast<Int128>(to.denominator) * from.numerator;
  return static_cast<std::int64_t>((num + den - 1) / den);
}

namespace {

// Output frame j at source position p: a copy of `frame` (source frame k), its low-level FAPs
// interpolated towards `next` (source frame k + 1, null when there is none) in linear mode.
void interpolate(FapFrame& frame, const FapFrame* next, const SourcePosition& p, ResampleMode mode,
                 CommonFaps& common) {
  if (mode != ResampleMode::kLinear || p.remainder == 0 || next == nullptr) return;
  const std::span<const int> faps = common.of(frame.mask, next->mask);
  auto lerp_all = [&](auto lerp) {
    for (const int fap : faps) {
      std::int32_t& v = frame.values[static_cast<std::size_t>(fap - 1)];
      v = lerp(v, next->value(fap));
    }
  };
  const std::int64_t num = p.remainder, den = p.denominator;
  if (den <= kMaxDenominatorDouble) {
    const auto den_d = static_cast<double>(den);
    lerp_all([&](std::int32_t a, std::int32_t b) { return lerp_rounded_double(a, b, num, den, den_d); });
  } else if (den <= kMaxDenominator64) {
    lerp_all([&](std::int32_t a, std::int32_t b) { return lerp_rounded<std::int64_t>(a, b, num, den); });
  } else {
    lerp_all([&](std::int32_t a, std::int32_t b) { return lerp_rounded<Int128>(a, b, num, den); });
  }
}

}  // namespace

FapSequence resample_track(const FapSequence& seq, FrameRate to,
                                  ResampleMode mode) {
  FapSequence out;
  out.name = seq.name;
  out.rate = to;
  const auto n = static_cast<std::int64_t>(seq.frames.size());
  const std::int64_t count = resampled_frame_count(n, seq.rate, to);
  out.frames.reserve(static_cast<std::size_t>(count));
  CommonFaps common;
  for (std::int64_t j = 0; j < count; ++j) {
    const SourcePosition p = source_position(j, seq.rate, to);
    const std::int64_t k = p.index < n ? p.index : n - 1;
    FapFrame& frame = out.frames.emplace_back(seq.frames[static_cast<std::size_t>(k)]);
    interpolate(frame, k + 1 < n ? &seq.frames[static_cast<std::size_t>(k + 1)] : nullptr, p, mode, common);
  }
  return out;
}

struct TrackResampler::Common : CommonFaps {};

TrackResampler::TrackResampler(FrameRate from, FrameRate to, ResampleMode mode, Sink sink)
    : from_(from), to_(to), mode_(mode), sink_(std::move(sink)), common_(std::make_unique<Common>()) {}

TrackResampler::~TrackResampler() = default;

void TrackResampler::emit(std::int64_t n) {
  // Every output frame whose source frames k and k + 1 are both in (or, at the end, the rest).
  for (;;) {
    if (finished_ && next_ >= resampled_frame_count(n, from_, to_)) break;
    const SourcePosition p = source_position(next_, from_, to_);
    const std::int64_t available = first_ + static_cast<std::int64_t>(window_.size());
    if (!finished_ && p.index + 1 >= available) break;
    const std::int64_t k = p.index < n ? p.index : n - 1;
    FapFrame frame = window_[static_cast<std::size_t>(k - first_)];
    const bool has_next = k + 1 < n;
    interpolate(frame, has_next ? &window_[static_cast<std::size_t>(k + 1 - first_)] : nullptr, p, mode_, *common_);
    sink_(next_, frame);
    ++next_;
    // Source frames before k are never needed again.
    const auto drop = static_cast<std::size_t>(std::min<std::int64_t>(k - first_, static_cast<std::int64_t>(window_.size())));
    window_.erase(window_.begin(), window_.begin() + static_cast<std::ptrdiff_t>(drop));
    first_ += static_cast<std::int64_t>(drop);
  }
}

void TrackResampler::push(const FapFrame& frame) {
  if (finished_) throw std::logic_error("TrackResampler: push after finish");
  window_.push_back(frame);
  ++pushed_;
  emit(pushed_);
}

void TrackResampler::finish() {
  if (finished_) return;
  finished_ = true;
  if (pushed_ > 0) emit(pushed_);
}

}  // namespace fapcast
