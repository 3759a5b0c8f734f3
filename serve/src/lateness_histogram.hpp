#pragma once
// How late frames leave against their deadlines: a fixed histogram of 10 µs bins up to 100 ms
// (later ones in the last bin), so that percentiles cost no memory growth however long it runs.
// One thread adds (the frame pacer), any thread reads, without a lock: a real-time pacer must
// never wait for a reader that the scheduler has preempted (priority inversion). A read while
// adds go on may see a count a few adds ahead of the bins: quantiles are of the bins read.
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>

namespace fapcast {

class LatenessHistogram {
 public:
  static constexpr std::int64_t kBinNanoseconds = 10'000;
  static constexpr std::size_t kBins = 10'000;

  // The one writer's.
  void add(std::chrono::nanoseconds late) {
    const std::int64_t ns = late.count() < 0 ? 0 : late.count();
    const auto bin = static_cast<std::size_t>(ns / kBinNanoseconds);
    bins_[bin < kBins ? bin : kBins - 1].fetch_add(1, std::memory_order_relaxed);
    if (ns > max_.load(std::memory_order_relaxed)) max_.store(ns, std::memory_order_relaxed);
  }
  std::chrono::nanoseconds max() const { return std::chrono::nanoseconds(max_.load(std::memory_order_relaxed)); }
  // The upper edge of the bin holding quantile q (0..1); 0 when empty.
  std::chrono::nanoseconds quantile(double q) const {
    std::array<std::uint32_t, kBins> bins;
    std::uint64_t count = 0;
    for (std::size_t b = 0; b < kBins; ++b) count += bins[b] = bins_[b].load(std::memory_order_relaxed);
    if (count == 0) return {};
    const auto rank = static_cast<std::uint64_t>(q * static_cast<double>(count - 1)) + 1;
    std::uint64_t seen = 0;
    for (std::size_t b = 0; b < kBins; ++b)
      if ((seen += bins[b]) >= rank) return std::chrono::nanoseconds((static_cast<std::int64_t>(b) + 1) * kBinNanoseconds);
    return max();
  }

 private:
  std::array<std::atomic<std::uint32_t>, kBins> bins_{};
  std::atomic<std::int64_t> max_{0};
};

}  // namespace fapcast
