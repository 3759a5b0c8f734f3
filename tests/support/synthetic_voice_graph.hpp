#pragma once
// A SYNTHETIC stand-in for a voice's search data: recordings of random phones whose PCA frames
// hold a known per-class shape (so tests can see what was concatenated) plus optional noise. Not a
// voice: no mesh, no retargeting.
#include "fapcast/select/phone_graph.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

namespace fapcast::test {

struct SyntheticVoiceGraph {
  std::vector<PhoneState> states;
  // corpus frames x k, row-major as a voice maps them (PcaFrames): the benchmarks measure no copy
  Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> frames;
  std::unique_ptr<PhoneGraph> graph;
};

// Coefficient c of class v's shape: column 0 is -1 for bilabials (a closure) and 1 + v / 10
// otherwise; column c > 0 is sin(v + c).
inline float class_shape(VisemeClass v, Eigen::Index c) {
  const auto i = static_cast<int>(v);
  if (c > 0) return static_cast<float>(std::sin(i + static_cast<int>(c)));
  return v == VisemeClass::kBilabial ? -1.0f : 1.0f + static_cast<float>(i) / 10.0f;
}

// `recordings` x `phones_per_recording` states of random classes drawn from `classes` (all 21
// when empty), `frames_per_phone` frames each (or, when `max_frames_per_phone` is larger, a
// uniform random count from frames_per_phone to it), k columns; noise is N(0, noise^2).
inline SyntheticVoiceGraph synthetic_voice_graph(std::uint32_t recordings, int phones_per_recording,
                                                 std::uint32_t frames_per_phone, Eigen::Index k,
                                                 std::uint64_t seed, float noise = 0.0f,
                                                 std::vector<VisemeClass> classes = {},
                                                 bool join_features = true,
                                                 std::uint32_t max_frames_per_phone = 0) {
  if (classes.empty())
    for (std::size_t v = 0; v < kVisemeClassCount; ++v) classes.push_back(static_cast<VisemeClass>(v));
  SyntheticVoiceGraph g;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, classes.size() - 1);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  std::uniform_int_distribution<std::uint32_t> count(frames_per_phone, std::max(frames_per_phone, max_frames_per_phone));
  std::uint32_t f = 0;
  for (std::uint32_t u = 0; u < recordings; ++u)
    for (int p = 0; p < phones_per_recording; ++p) {
      const VisemeClass v = classes[pick(rng)];
      const std::uint32_t n = max_frames_per_phone > frames_per_phone ? count(rng) : frames_per_phone;
      g.states.push_back({u, v, {f, n}});
      f += n;
    }
  g.frames.resize(f, k);
  for (const auto& s : g.states)
    for (std::uint32_t n = s.frames.first; n < s.frames.first + s.frames.count; ++n)
      for (Eigen::Index c = 0; c < k; ++c)
        g.frames(n, c) = class_shape(s.viseme, c) + (noise > 0 ? noise * normal(rng) : 0.0f);
  g.graph = join_features ? std::make_unique<PhoneGraph>(g.states, fapcast::join_features(g.states, g.frames))
                              : std::make_unique<PhoneGraph>(g.states);
  return g;
}

}  // namespace fapcast::test
