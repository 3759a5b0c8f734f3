#pragma once
// Helpers the FBA tests share: their default seed, and smooth random tracks.
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/fba/fba_stream.hpp"
#include "support/test_seed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace fapcast::test {

// The default seed of the random FBA tests (support/test_seed.hpp).
inline constexpr std::uint64_t kFbaSeed = 20261122;

// A smooth random walk per masked FAP (a low-passed random walk), values within +/-limit.
inline std::vector<FapFrame> smooth_track(std::mt19937_64& rng, const FapMask& mask,
                                                 std::size_t frames, int limit) {
  std::vector<FapFrame> out(frames);
  std::normal_distribution<double> noise(0.0, limit / 40.0);
  std::vector<double> velocity(kFapCount + 1, 0.0), value(kFapCount + 1, 0.0);
  for (auto& f : out) {
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
      if (!mask.test(n)) continue;
      velocity[n] = 0.8 * velocity[n] + noise(rng);
      value[n] = std::clamp(0.98 * value[n] + velocity[n], -double(limit), double(limit));
      f.set(n, static_cast<std::int32_t>(std::lround(value[n])));
    }
  }
  return out;
}

// A random track: a random mask (FAP 1 and 2 included at random), smooth low-level values within
// +/-limit, random viseme and expression fields, the mask the same in every frame.
inline std::vector<FapFrame> random_track(std::mt19937_64& rng, std::size_t frames, int limit) {
  FapMask mask;
  for (int n = 1; n <= kFapCount; ++n) mask.set(n, rng() % 3 == 0);
  std::vector<FapFrame> out = smooth_track(rng, mask, frames, limit);
  for (FapFrame& f : out) {
    f.mask = mask;
    if (mask.test(1))
      f.viseme = {static_cast<std::uint8_t>(rng() % 15), static_cast<std::uint8_t>(rng() % 15),
                  static_cast<std::uint8_t>(rng() % 64), rng() % 2 == 0};
    if (mask.test(2))
      f.expression = {static_cast<std::uint8_t>(rng() % 7), static_cast<std::uint8_t>(rng() % 64),
                      static_cast<std::uint8_t>(rng() % 7), static_cast<std::uint8_t>(rng() % 64), rng() % 2 == 0,
                      rng() % 2 == 0};
  }
  return out;
}

// Encoder options: a profile, fap_quant and intra period (0: one intra frame, at the start).
inline FbaEncoderOptions encoder_options(FbaProfile profile, int fap_quant, int intra_period = 0) {
  FbaEncoderOptions o;
  o.profile = profile;
  o.fap_quant = fap_quant;
  o.intra_period = intra_period;
  return o;
}

// Where the runs of an .fba file begin: the byte offsets of its plane start codes (spec/fba.md §1).
inline std::vector<std::size_t> run_offsets(const std::vector<std::uint8_t>& b) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i + 3 < b.size(); ++i)
    if (b[i] == 0 && b[i + 1] == 0 && b[i + 2] == 1 && b[i + 3] == 0xBB) out.push_back(i);
  return out;
}

}  // namespace fapcast::test
