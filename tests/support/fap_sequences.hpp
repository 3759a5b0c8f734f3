#pragma once
// Generated FAP sequences for tests and benchmarks (header-only: the benchmarks link no test
// support library). SYNTHETIC data: random or patterned, not measured from any face.
#include "fapcast/codec/fap_frame.hpp"
#include "support/test_seed.hpp"

#include <cstdint>
#include <random>
#include <string>

namespace fapcast::test {

// The default seed of the random FAP-sequence tests (support/test_seed.hpp).
inline constexpr std::uint64_t kFapSequenceSeed = 20061201;

// A random frame: any mask (FAP 1 and 2 with valid fields), values anywhere in int32 with
// extremes and small values both likely.
inline FapFrame random_fap_frame(std::mt19937_64& rng) {
  FapFrame f;
  std::bernoulli_distribution coin(0.5);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const double density = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  std::bernoulli_distribution masked(density);
  if (masked(rng)) {
    f.mask.set(kVisemeFap);
    f.viseme = {static_cast<std::uint8_t>(uniform(0, 14)), static_cast<std::uint8_t>(uniform(0, 14)),
                static_cast<std::uint8_t>(uniform(0, 63)), coin(rng)};
  }
  if (masked(rng)) {
    f.mask.set(kExpressionFap);
    f.expression = {static_cast<std::uint8_t>(uniform(0, 6)), static_cast<std::uint8_t>(uniform(0, 63)),
                    static_cast<std::uint8_t>(uniform(0, 6)), static_cast<std::uint8_t>(uniform(0, 63)),
                    coin(rng), coin(rng)};
  }
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    if (!masked(rng)) continue;
    std::int32_t v = 0;
    switch (uniform(0, 3)) {
      case 0: v = uniform(-1000, 1000); break;
      case 1: v = std::uniform_int_distribution<std::int32_t>(INT32_MIN, INT32_MAX)(rng); break;
      case 2: v = coin(rng) ? INT32_MIN : INT32_MAX; break;
      default: v = 0;
    }
    f.set(n, v);
  }
  return f;
}

// A random sequence of `frames` frames; the name may hold spaces.
inline FapSequence random_fap_sequence(std::mt19937_64& rng, std::size_t frames) {
  static const FrameRate kRates[] = {{25, 1}, {30, 1}, {60, 1}, {30000, 1001}, {24000, 1001},
                                           {25, 2}, {1000, 1}, {1, 8}};
  FapSequence s;
  s.name = std::uniform_int_distribution<int>(0, 1)(rng) ? "random" : "random name with spaces";
  s.rate = kRates[std::uniform_int_distribution<std::size_t>(0, std::size(kRates) - 1)(rng)];
  for (std::size_t i = 0; i < frames; ++i) s.frames.push_back(random_fap_frame(rng));
  return s;
}

// A long talking-head-like track: the mask Xface's exporter writes (FAPs 3-26, 31-42, 48-60,
// 63) and smooth values of realistic size (tens to hundreds of FAPU), at 25 fps.
inline FapSequence realistic_fap_sequence(std::size_t frames) {
  FapSequence s;
  s.name = "synthetic-benchmark";
  s.rate = {25, 1};
  s.frames.reserve(frames);
  for (std::size_t k = 0; k < frames; ++k) {
    FapFrame f;
    for (int n = 3; n <= 63; ++n) {
      if ((n >= 27 && n <= 30) || (n >= 43 && n <= 47) || n == 61 || n == 62) continue;
      const auto phase = static_cast<std::int64_t>(k * 7 + static_cast<std::size_t>(n) * 13);
      f.set(n, static_cast<std::int32_t>((phase % 400) - 120));
    }
    s.frames.push_back(f);
  }
  return s;
}

}  // namespace fapcast::test
