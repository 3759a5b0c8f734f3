#pragma once
// How late frames leave against their deadlines: a fixed histogram of 10 µs bins up to 100 ms
// (later ones in the last bin), so that percentiles cost no memory growth however long it runs.
#include <array>
#include <chrono>
#include <cstdint>

namespace fapcast {

class LatenessHistogram {
 public:
  static constexpr std::int64_t kBinNanoseconds = 10'000;
  static constexpr std::size_t kBins = 10'000;

  void add(std::chrono::nanoseconds late) {
    const std::int64_t ns = late.count() < 0 ? 0 : late.count();
    const auto bin = static_cast<std::size_t>(ns / kBinNanoseconds);
    ++bins_[bin < kBins ? bin : kBins - 1];
    ++count_;
    if (ns > max_) max_ = ns;
  }
  std::uint64_t count() const { return count_; }
  std::chrono::nanoseconds max() const { return std::chrono::nanoseconds(max_); }
  // The upper edge of the bin holding quantile q (0..1); 0 when empty.
  std::chrono::nanoseconds quantile(double q) const {
    if (count_ == 0) return {};
    const auto rank = static_cast<std::uint64_t>(q * static_cast<double>(count_ - 1)) + 1;
    std::uint64_t seen = 0;
    for (std::size_t b = 0; b < kBins; ++b)
      if ((seen += bins_[b]) >= rank) return std::chrono::nanoseconds((static_cast<std::int64_t>(b) + 1) * kBinNanoseconds);
    return max();
  }

 private:
  std::array<std::uint32_t, kBins> bins_{};
  std::uint64_t count_ = 0;
  std::int64_t max_ = 0;
};

}  // namespace fapcast
