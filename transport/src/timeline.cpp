#include "fapcast/transport/timeline.hpp"

#include "fapcast/core/frame_rate.hpp"

namespace fapcast {
namespace {
__extension__ typedef __int128 Int128;
constexpr std::int64_t kNanosPerSecond = 1'000'000'000;
}  // namespace

std::chrono::nanoseconds samples_to_duration(std::int64_t sample, SampleRate sample_rate) {
  return std::chrono::nanoseconds(
      static_cast<std::int64_t>(static_cast<Int128>(sample) * kNanosPerSecond / sample_rate.hz));
}

std::int64_t duration_to_samples(std::chrono::nanoseconds t, SampleRate sample_rate) {
  return static_cast<std::int64_t>(static_cast<Int128>(t.count()) * sample_rate.hz / kNanosPerSecond);
}

std::vector<TimedFrame> place_on_timeline(const FapSequence& seq,
                                          SampleRate sample_rate) {
  std::vector<TimedFrame> out;
  out.reserve(seq.frames.size());
  for (std::size_t k = 0; k < seq.frames.size(); ++k)
    out.push_back({frame_to_sample(static_cast<std::int64_t>(k), seq.rate, sample_rate),
                   seq.frames[k]});
  return out;
}

}  // namespace fapcast
