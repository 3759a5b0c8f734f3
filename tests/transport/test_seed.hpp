#pragma once
// The default seed of the random transport tests (support/test_seed.hpp: FAPCAST_SEED replaces it).
#include "support/test_seed.hpp"

#include <cstdint>

namespace fapcast::test {

inline constexpr std::uint64_t kTransportSeed = 20261122;

}  // namespace fapcast::test
