#pragma once
// The seed of a random test: env FAPCAST_SEED, else a fixed default; printed with the command
// that reproduces the run.
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

namespace fapcast::test {

inline std::uint64_t test_seed() {
  const char* env = std::getenv("FAPCAST_SEED");
  const std::uint64_t seed = env ? std::strtoull(env, nullptr, 10) : 20261122;
  std::cerr << "[seed] FAPCAST_SEED=" << seed << " reproduces this run\n";
  return seed;
}

}  // namespace fapcast::test
