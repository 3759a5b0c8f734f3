#pragma once
// Helpers for the corpus-format tests: fixture bytes, and seeded random alignments and marker
// sets (seed from FAPCAST_SEED, printed so a failure can be reproduced).
#include "fapcast/corpus/alignment.hpp"
#include "fapcast/corpus/marker_frames.hpp"
#include "support/test_seed.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

namespace fapcast::test {

inline std::filesystem::path corpus_data() { return std::filesystem::path(FAPCAST_TEST_DATA) / "corpus"; }

inline std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The default seed of the random corpus-format tests (support/test_seed.hpp).
inline constexpr std::uint64_t kCorpusSeed = 20061001;

// A random label: ASCII, quotes, IPA, emoji and (for TextGrid) line breaks.
inline std::string random_label(std::mt19937_64& rng, bool allow_space) {
  static const char* const pieces[] = {"a", "sh", "\"", "\"\"", "ʃ", "iː", "😀", "ə", "p", "_", "-", "1"};
  std::string s;
  const int n = static_cast<int>(rng() % 4);
  for (int i = 0; i < n; ++i) s += pieces[rng() % std::size(pieces)];
  if (allow_space && rng() % 5 == 0) s += rng() % 2 ? " x" : "\nnext line";
  return s;
}

// A valid alignment: 0-3 tiers of contiguous intervals or increasing points on random times.
inline Alignment random_alignment(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> step(1e-4, 0.4);
  Alignment a;
  a.start_s = rng() % 3 == 0 ? step(rng) : 0.0;
  a.end_s = a.start_s + 0.5 + step(rng) * 10;
  const int tiers = static_cast<int>(rng() % 4);
  for (int t = 0; t < tiers; ++t) {
    LabelTier tier;
    tier.name = t == 0 ? "phones" : random_label(rng, true);
    tier.kind = rng() % 3 == 0 ? TierKind::points : TierKind::intervals;
    tier.start_s = a.start_s;
    tier.end_s = a.end_s;
    double at = tier.start_s;
    for (;;) {
      const double next = at + step(rng);
      if (next >= tier.end_s) break;
      if (tier.kind == TierKind::intervals) {
        tier.intervals.push_back({at, next, random_label(rng, true)});
      } else {
        tier.points.push_back({next, random_label(rng, true)});
      }
      at = next;
    }
    if (tier.kind == TierKind::intervals) tier.intervals.push_back({at, tier.end_s, ""});
    a.tiers.push_back(std::move(tier));
  }
  return a;
}

// Random float-valued positions (mm) with about 5% missing samples.
inline MarkerFrames<Millimetres> random_markers(std::mt19937_64& rng, Eigen::Index frames, Eigen::Index markers) {
  MarkerFrames<Millimetres> m = MarkerFrames<Millimetres>::zeros(markers, frames);
  std::uniform_real_distribution<float> mm(-300.0F, 300.0F);
  for (Eigen::Index i = 0; i < markers; ++i) m.labels[static_cast<std::size_t>(i)] = "M" + std::to_string(i) + (i % 3 ? ".x" : "");
  for (Eigen::Index f = 0; f < frames; ++f) {
    for (Eigen::Index i = 0; i < markers; ++i) {
      if (rng() % 20 == 0) {
        m.drop(i, f);
        continue;
      }
      m.set(i, f, Eigen::Vector3d(mm(rng), mm(rng), mm(rng)));
    }
  }
  m.frame_rate_hz = 60;
  return m;
}

}  // namespace fapcast::test
