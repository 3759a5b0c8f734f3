#pragma once
// Seeded random numbers that are the same on every standard library: std::mt19937_64's output
// sequence is fixed by the C++ standard, but std::uniform_real_distribution and
// std::normal_distribution are not (libstdc++ and libc++ differ), so the distributions are
// implemented here. Results then depend only on the seed and on libm's exp/log/sin/cos, which
// are correctly rounded or nearly so on the toolchains we build with (glibc, x86-64).
#include <cstdint>
#include <random>

namespace fapcast {

class PortableRandom {
 public:
  explicit PortableRandom(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1): the top 53 bits of one engine output.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // Uniform in [low, high).
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  // Standard normal (Box-Muller; the second variate is kept for the next call).
  double normal();
  // Uniform integer in [0, n), n >= 1 (rejection sampling: no modulo bias).
  std::uint64_t below(std::uint64_t n);
  // An independent stream for a sub-task (e.g. one take), derived from this one.
  PortableRandom split() { return PortableRandom(engine_() ^ 0x9E3779B97F4A7C15ull); }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace fapcast
