#include "pauses.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace fapcast {

std::vector<Pause> find_pauses(std::span<const std::int16_t> samples, const PauseSettings& settings) {
  const auto n = static_cast<std::size_t>(static_cast<std::int64_t>(samples.size()) / settings.frame_samples);
  std::vector<double> db(n);
  for (std::size_t f = 0; f < n; ++f) {
    double sum = 0;
    for (std::int64_t k = 0; k < settings.frame_samples; ++k) {
      const double v = samples[f * static_cast<std::size_t>(settings.frame_samples) + static_cast<std::size_t>(k)];
      sum += v * v;
    }
    db[f] = 10.0 * std::log10(sum / static_cast<double>(settings.frame_samples) + 1.0);
  }
  std::vector<Pause> out;
  if (n == 0) return out;
  std::vector<double> sorted = db;
  std::sort(sorted.begin(), sorted.end());
  const double floor = sorted[n / 10], level = sorted[n * 9 / 10];
  if (level - floor < settings.min_contrast_db) return out;
  const double quiet = floor + settings.quiet_share * (level - floor);
  std::size_t run = 0;
  for (std::size_t f = 0; f <= n; ++f) {
    if (f < n && db[f] < quiet) {
      ++run;
      continue;
    }
    if (run >= static_cast<std::size_t>(settings.min_pause_frames))
      out.push_back({static_cast<std::int64_t>(f - run) * settings.frame_samples,
                     static_cast<std::int64_t>(f) * settings.frame_samples});
    run = 0;
  }
  return out;
}

std::vector<std::int64_t> cut_points(const std::vector<Pause>& pauses, std::int64_t length, std::int64_t min_piece,
                                     std::int64_t max_piece) {
  std::vector<std::int64_t> cuts;
  std::int64_t start = 0;
  std::size_t p = 0;
  while (true) {
    const Pause* best = nullptr;
    for (; p < pauses.size(); ++p) {
      const std::int64_t mid = (pauses[p].start + pauses[p].end) / 2;
      if (mid < start + min_piece) continue;
      if (mid > start + max_piece && best) break;
      if (!best || pauses[p].end - pauses[p].start > best->end - best->start) best = &pauses[p];
      if (mid > start + max_piece) break;  // the first pause after the window
    }
    if (!best) break;
    const std::int64_t cut = (best->start + best->end) / 2;
    if (length - cut < min_piece / 2) break;
    cuts.push_back(cut);
    start = cut;
    p = static_cast<std::size_t>(best - pauses.data()) + 1;
  }
  return cuts;
}

}  // namespace fapcast
