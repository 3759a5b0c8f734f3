#include "fapcast/synth/unit_render.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace fapcast::synth {
namespace {

// The frame range [lo, hi] of the recording that holds state j: warping may run past the
// state's own span into its neighbours (that is what makes cross-fades seamless), not further.
struct RecordingFrames {
  std::int64_t lo, hi;
};

// The recording of state j: O(its length), so a render never walks the whole corpus.
RecordingFrames recording_frames(const PhoneGraph& graph, StateId j) {
  StateId first = j, last = j;
  while (graph.has_parent(first)) --first;
  while (graph.has_child(last)) ++last;
  const auto& end = graph.state(last).frames;
  return {graph.state(first).frames.first, std::int64_t{end.first} + end.count - 1};
}

// Linear time warp of state j's span onto target frames [s, e): where output frame n samples
// the recording (fractional frame index; may lie outside the span for n outside [s, e)).
double warp(const FrameSpan& span, std::int64_t s, std::int64_t e, std::int64_t n) {
  const double scale = static_cast<double>(span.count) / static_cast<double>(e - s);
  return span.first + (static_cast<double>(n - s) + 0.5) * scale - 0.5;
}

// The recording's PCA vector at fractional frame p, clamped to the recording: an expression over
// two rows of `frames` (nothing allocated).
auto sample(const Eigen::MatrixXf& frames, RecordingFrames r, double p) {
  p = std::clamp(p, static_cast<double>(r.lo), static_cast<double>(r.hi));
  const auto i0 = static_cast<std::int64_t>(std::floor(p));
  const auto i1 = std::min(i0 + 1, r.hi);
  const float f = static_cast<float>(p - static_cast<double>(i0));
  return (1.0f - f) * frames.row(static_cast<Eigen::Index>(i0)) + f * frames.row(static_cast<Eigen::Index>(i1));
}

}  // namespace

Eigen::MatrixXf render_units(const PhoneGraph& graph, const Eigen::MatrixXf& pca_frames,
                             const SearchResult& result, std::span<const TargetPhone> targets,
                             const RenderOptions& options) {
  if (result.states.size() != targets.size())
    throw std::invalid_argument("render: " + std::to_string(result.states.size()) +
                                " selected states for " + std::to_string(targets.size()) + " target phones");
  if (targets.empty()) return Eigen::MatrixXf(0, pca_frames.cols());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    if (targets[t].end_frame <= targets[t].first_frame)
      throw std::invalid_argument("render: target phone " + std::to_string(t) + " spans no frames");
    if (t > 0 && targets[t].first_frame != targets[t - 1].end_frame)
      throw std::invalid_argument("render: target phone " + std::to_string(t) +
                                  " does not start where the previous one ends");
  }
  // The recording of each target's state (consecutive states of one recording share it).
  std::vector<RecordingFrames> recordings(targets.size());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const StateId j = result.states[t];
    const bool same = t > 0 && graph.state(j).utterance == graph.state(result.states[t - 1]).utterance;
    recordings[t] = same ? recordings[t - 1] : recording_frames(graph, j);
  }
  const std::int64_t origin = targets.front().first_frame;
  const std::int64_t frames = targets.back().end_frame - origin;
  Eigen::MatrixXf out(static_cast<Eigen::Index>(frames), pca_frames.cols());
  std::vector<double> weights(static_cast<std::size_t>(frames), 1.0);

  // Each target phone samples its own state through its own warp.
  auto at = [&](std::size_t t, std::int64_t n) {
    const StateId j = result.states[t];
    return sample(pca_frames, recordings[t], warp(graph.state(j).frames, targets[t].first_frame, targets[t].end_frame, n));
  };
  for (std::size_t t = 0; t < targets.size(); ++t)
    for (std::int64_t n = targets[t].first_frame; n < targets[t].end_frame; ++n) {
      out.row(static_cast<Eigen::Index>(n - origin)) = at(t, n);
      if (targets[t].hold) weights[static_cast<std::size_t>(n - origin)] = options.hold_weight;
    }

  // Cross-fade at each join: the unit that ends runs on into its own recording, the one that
  // starts runs back into its own, and a raised cosine hands one over to the other. A mid-phone
  // join hands over in the middle of target t - 1, the new unit showing its parent state there.
  const int h = std::max(0, options.blend_half_width);
  for (std::size_t u = 1; u < result.units.size(); ++u) {
    const std::size_t t = result.units[u].first_target;  // first phone of the new unit
    const StateId j = result.states[t];
    const bool mid = options.join_mid_phone && graph.has_parent(j) &&
                     graph.state(j - 1).viseme == graph.state(result.states[t - 1]).viseme;
    const TargetPhone& before = targets[t - 1];
    // The new unit at frame n: its own state's warp on target t, or (mid-phone) its parent's on t - 1.
    auto incoming = [&](std::int64_t n) {
      if (!mid || n >= before.end_frame) return Eigen::RowVectorXf(at(t, n));
      return Eigen::RowVectorXf(sample(pca_frames, recordings[t], warp(graph.state(j - 1).frames, before.first_frame, before.end_frame, n)));
    };
    const std::int64_t join = mid ? before.first_frame + (before.end_frame - before.first_frame) / 2 : targets[t].first_frame;
    const std::int64_t lo = std::max(join - h, before.first_frame);
    const std::int64_t hi = std::min(join + h, mid ? before.end_frame : targets[t].end_frame);
    for (std::int64_t n = lo; n < hi; ++n) {
      const double x = (static_cast<double>(n - lo) + 0.5) / static_cast<double>(hi - lo);
      const float w = static_cast<float>(0.5 - 0.5 * std::cos(std::numbers::pi * x));
      out.row(static_cast<Eigen::Index>(n - origin)) = (1.0f - w) * at(t - 1, n) + w * incoming(n);
    }
    if (mid)  // after the fade, the rest of target t - 1 is the new unit's
      for (std::int64_t n = std::max(hi, join); n < before.end_frame; ++n) out.row(static_cast<Eigen::Index>(n - origin)) = incoming(n);
  }
  return options.smoothing > 0.0 ? smooth_trajectory(out, weights, options.smoothing) : out;
}

Eigen::MatrixXf smooth_trajectory(const Eigen::MatrixXf& x, std::span<const double> weights,
                                  double lambda) {
  const auto n = static_cast<std::size_t>(x.rows());
  if (weights.size() != n) throw std::invalid_argument("smooth: one weight per frame expected");
  if (n < 3 || lambda <= 0.0) return x;
  // (W + lambda D'D) y = W x with D the (n-2) x n second-difference operator: a symmetric
  // pentadiagonal system. Its LDL' factor keeps the band, so one O(n) factorisation serves all
  // k columns. a0, a1, a2: the diagonal and the first and second super-diagonals.
  std::vector<double> a0(weights.begin(), weights.end()), a1(n, 0.0), a2(n, 0.0);
  constexpr double d[3] = {1.0, -2.0, 1.0};
  for (std::size_t r = 0; r + 2 < n; ++r)
    for (std::size_t p = 0; p < 3; ++p) {
      a0[r + p] += lambda * d[p] * d[p];
      if (p < 2) a1[r + p] += lambda * d[p] * d[p + 1];
      if (p < 1) a2[r + p] += lambda * d[p] * d[p + 2];
    }
  // L(i, i-1) = l1[i], L(i, i-2) = l2[i], D = diag(dd).
  std::vector<double> dd(n), l1(n, 0.0), l2(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (i >= 2) l2[i] = a2[i - 2] / dd[i - 2];
    if (i >= 1) l1[i] = (a1[i - 1] - (i >= 2 ? l2[i] * l1[i - 1] * dd[i - 2] : 0.0)) / dd[i - 1];
    dd[i] = a0[i] - (i >= 1 ? l1[i] * l1[i] * dd[i - 1] : 0.0) - (i >= 2 ? l2[i] * l2[i] * dd[i - 2] : 0.0);
    if (!(dd[i] > 0.0)) throw std::invalid_argument("smooth: weights must be positive");
  }
  // The same substitutions for all k columns at once, a frame (row) at a time.
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Rows z = x.cast<double>();
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    z.row(r) *= weights[i];
    if (i >= 1) z.row(r) -= l1[i] * z.row(r - 1);
    if (i >= 2) z.row(r) -= l2[i] * z.row(r - 2);
  }
  for (std::size_t i = 0; i < n; ++i) z.row(static_cast<Eigen::Index>(i)) /= dd[i];
  for (std::size_t i = n; i-- > 0;) {
    const auto r = static_cast<Eigen::Index>(i);
    if (i + 1 < n) z.row(r) -= l1[i + 1] * z.row(r + 1);
    if (i + 2 < n) z.row(r) -= l2[i + 2] * z.row(r + 2);
  }
  Eigen::MatrixXf y = z.cast<float>();
  return y;
}

}  // namespace fapcast::synth
