#pragma once
// The seed of a random test: env FAPCAST_SEED when set, else a fixed default, so a failure
// reproduces with `FAPCAST_SEED=<printed seed> <test binary> --gtest_filter=<test>`.
#include <cstdint>
#include <cstdlib>

namespace fapcast::test {

inline std::uint64_t seed_from_env(std::uint64_t fallback = 20261122u) {
  const char* env = std::getenv("FAPCAST_SEED");
  return env != nullptr ? std::strtoull(env, nullptr, 10) : fallback;
}

}  // namespace fapcast::test
