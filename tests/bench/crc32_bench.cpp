// CRC-32 of a buffer the size of the default voice file (17.5 MB; every section is checked at
// open): fapcast::crc32 (libdeflate) against zlib's crc32_z, its former implementation, in the
// same run, over the same bytes. Both must give the same value (checked before timing).
#include <benchmark/benchmark.h>
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "fapcast/core/crc32.hpp"

namespace {

constexpr std::size_t kVoiceBytes = 17'466'656;  // the default voice, recipe 9

const std::vector<std::byte>& voice_sized_buffer() {
  static const std::vector<std::byte> bytes = [] {
    std::vector<std::byte> b(kVoiceBytes);
    std::uint32_t x = 0x9E3779B9u;
    for (std::byte& v : b) {  // xorshift: bytes that are not all alike
      x ^= x << 13, x ^= x >> 17, x ^= x << 5;
      v = static_cast<std::byte>(x >> 24);
    }
    const auto zlib = ::crc32_z(0, reinterpret_cast<const Bytef*>(b.data()), b.size());
    if (fapcast::crc32(b) != zlib) throw std::logic_error("crc32_bench: libdeflate and zlib disagree");
    return b;
  }();
  return bytes;
}

void rate(benchmark::State& state) {
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(kVoiceBytes));
}

void BM_Crc32_Fapcast(benchmark::State& state) {
  const auto& b = voice_sized_buffer();
  for (auto _ : state) benchmark::DoNotOptimize(fapcast::crc32(b));
  rate(state);
}
BENCHMARK(BM_Crc32_Fapcast)->Unit(benchmark::kMillisecond);

void BM_Crc32_ZlibCrc32z(benchmark::State& state) {
  const auto& b = voice_sized_buffer();
  for (auto _ : state) benchmark::DoNotOptimize(::crc32_z(0, reinterpret_cast<const Bytef*>(b.data()), b.size()));
  rate(state);
}
BENCHMARK(BM_Crc32_ZlibCrc32z)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
