#include "fapcast/codec/fap_stats.hpp"

#include <algorithm>
#include <array>

namespace fapcast {

FapStats fap_stats(const FapSequence& seq) {
  FapStats s;
  s.frame_count = seq.frames.size();
  s.rate = seq.rate;
  constexpr SampleRate kMilliseconds{1000};  // the duration as samples of a 1 kHz clock
  s.duration_ms = frame_to_sample(static_cast<std::int64_t>(s.frame_count), seq.rate, kMilliseconds);
  std::array<FapValueRange, kFapCount> all{};
  for (const FapFrame& f : seq.frames) {
    for (int n = 1; n <= kFapCount; ++n) {
      if (!f.mask.test(n)) continue;
      const std::int32_t v = n == kVisemeFap       ? f.viseme.select1
                             : n == kExpressionFap ? f.expression.select1
                                                   : f.value(n);
      FapValueRange& r = all[static_cast<std::size_t>(n - 1)];
      r.min = r.frames_masked == 0 ? v : std::min(r.min, v);
      r.max = r.frames_masked == 0 ? v : std::max(r.max, v);
      ++r.frames_masked;
    }
    if (f.mask.test(kVisemeFap)) {
      s.visemes_used.set(std::min<std::size_t>(f.viseme.select1, 14));
      if (f.viseme.blend < 63) s.visemes_used.set(std::min<std::size_t>(f.viseme.select2, 14));
    }
    if (f.mask.test(kExpressionFap)) {
      s.expressions_used.set(std::min<std::size_t>(f.expression.select1, 6));
      if (f.expression.intensity2 > 0)
        s.expressions_used.set(std::min<std::size_t>(f.expression.select2, 6));
    }
  }
  for (int n = 1; n <= kFapCount; ++n) {
    FapValueRange r = all[static_cast<std::size_t>(n - 1)];
    if (r.frames_masked == 0) continue;
    r.fap = n;
    s.masked_faps.push_back(r);
  }
  return s;
}

}  // namespace fapcast
