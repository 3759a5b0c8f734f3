#pragma once
// The seed of a randomised test. FAPCAST_SEED (a decimal number) replaces the suite's default, so
// the seed a failure prints runs it again; anything else there fails the test instead of running
// it with a seed nobody chose.
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace fapcast::test {

inline std::uint64_t test_seed(std::uint64_t suite_default) {
  const char* text = std::getenv("FAPCAST_SEED");
  if (text == nullptr) return suite_default;
  const std::string_view s(text);
  std::uint64_t seed = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), seed);
  if (s.empty() || error != std::errc{} || end != s.data() + s.size()) {
    // Appended piece by piece: GCC 12 at -O3 warns falsely (-Wrestrict) on "literal" + string.
    std::string message = "FAPCAST_SEED=\"";
    message.append(s).append("\" is not a seed: a decimal number from 0 to 2^64 - 1");
    throw std::invalid_argument(message);
  }
  return seed;
}

// What a failure says to see it again (the failing test's name is in gtest's own report).
inline std::string reproduce_hint(std::uint64_t seed) {
  std::string hint = "reproduce with FAPCAST_SEED=";
  return hint.append(std::to_string(seed));
}

}  // namespace fapcast::test
