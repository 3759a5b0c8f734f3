#include "fapcast/synthesis/unit_concatenation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace fapcast {
namespace {

// The frame range [lo, hi] of the recording that holds state j: warping may run past the
// state's own span into its neighbours (that is what makes cross-fades seamless), not further.
struct RecordingFrames {
  std::int64_t lo, hi;
};

// The recording of state j: O(its length), so a concatenation never walks the whole corpus.
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

// Where frame p (fractional) of a recording is read: rows i0 and i1 mixed as (1 - f) : f, clamped
// to the recording.
struct Tap {
  Eigen::Index i0, i1;
  float f;
};
Tap tap(RecordingFrames r, double p) {
  p = std::clamp(p, static_cast<double>(r.lo), static_cast<double>(r.hi));
  const auto i0 = static_cast<std::int64_t>(p);  // floor: p >= r.lo >= 0
  const auto i1 = std::min(i0 + 1, r.hi);
  return {static_cast<Eigen::Index>(i0), static_cast<Eigen::Index>(i1), static_cast<float>(p - static_cast<double>(i0))};
}

// The banded LDL' factor of W + lambda D'D, D the (n-2) x n second-difference operator: a
// symmetric pentadiagonal matrix whose factor keeps the band, so one O(n) factorisation serves
// all k columns. L(i, i-1) = l1[i], L(i, i-2) = l2[i], D = diag(d).
struct SmoothingFactor {
  std::vector<double> d, l1, l2;
};

SmoothingFactor factor_smoother(std::span<const double> weights, double lambda) {
  const std::size_t n = weights.size();
  // a0, a1, a2: the diagonal and the first and second super-diagonals.
  std::vector<double> a0(weights.begin(), weights.end()), a1(n, 0.0), a2(n, 0.0);
  constexpr double d[3] = {1.0, -2.0, 1.0};
  for (std::size_t r = 0; r + 2 < n; ++r)
    for (std::size_t p = 0; p < 3; ++p) {
      a0[r + p] += lambda * d[p] * d[p];
      if (p < 2) a1[r + p] += lambda * d[p] * d[p + 1];
      if (p < 1) a2[r + p] += lambda * d[p] * d[p + 2];
    }
  SmoothingFactor f{std::vector<double>(n), std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  auto& dd = f.d;
  auto& l1 = f.l1;
  auto& l2 = f.l2;
  for (std::size_t i = 0; i < n; ++i) {
    if (i >= 2) l2[i] = a2[i - 2] / dd[i - 2];
    if (i >= 1) l1[i] = (a1[i - 1] - (i >= 2 ? l2[i] * l1[i - 1] * dd[i - 2] : 0.0)) / dd[i - 1];
    dd[i] = a0[i] - (i >= 1 ? l1[i] * l1[i] * dd[i - 1] : 0.0) - (i >= 2 ? l2[i] * l2[i] * dd[i - 2] : 0.0);
    if (!(dd[i] > 0.0)) throw std::invalid_argument("smooth: weights must be positive");
  }
  return f;
}

// The smoother's two substitutions over frames held row-major (frame i at z + i k, k values),
// all k columns at once. Forward: row i, given as x_i, becomes row i of L^-1 W x; rows before it
// must be done. Backward: every row forward-substituted, z becomes y = L'^-1 D^-1 L^-1 W x, written
// to `out` (frames x k). The operations and their order are those of the textbook loops (row *= w,
// row -= l1 prev, row -= l2 prev2), one pass per row.
void forward_substitute(const SmoothingFactor& f, std::span<const double> weights, std::size_t i,
                        double* z, std::size_t k) {
  double* __restrict row = z + i * k;
  const double w = weights[i];
  if (i < 2) {
    for (std::size_t c = 0; c < k; ++c) row[c] *= w;
    if (i == 1)
      for (std::size_t c = 0; c < k; ++c) row[c] -= f.l1[1] * z[c];
    return;
  }
  const double* __restrict prev = row - k;
  const double* __restrict prev2 = row - 2 * k;
  const double l1 = f.l1[i], l2 = f.l2[i];
  for (std::size_t c = 0; c < k; ++c) row[c] = (row[c] * w - l1 * prev[c]) - l2 * prev2[c];
}

void backward_substitute(const SmoothingFactor& f, double* z, std::size_t k, Eigen::MatrixXf& out) {
  const std::size_t n = f.d.size();
  float* y = out.data();  // column-major: frame i, column c at y[c n + i]
  for (std::size_t i = n; i-- > 0;) {
    double* __restrict row = z + i * k;
    const double d = f.d[i];
    if (i + 2 < n) {
      const double* __restrict next = row + k;
      const double* __restrict next2 = row + 2 * k;
      const double l1 = f.l1[i + 1], l2 = f.l2[i + 2];
      for (std::size_t c = 0; c < k; ++c) row[c] = (row[c] / d - l1 * next[c]) - l2 * next2[c];
    } else {
      for (std::size_t c = 0; c < k; ++c) row[c] /= d;
      if (i + 1 < n)
        for (std::size_t c = 0; c < k; ++c) row[c] -= f.l1[i + 1] * row[k + c];
    }
    for (std::size_t c = 0; c < k; ++c) y[c * n + i] = static_cast<float>(row[c]);
  }
}

}  // namespace

Eigen::MatrixXf concatenate_units(const PhoneGraph& graph, const PcaFrames& pca_frames,
                             const SearchResult& result, std::span<const TargetPhone> targets,
                             const ConcatenationOptions& options) {
  if (result.states.size() != targets.size())
    throw std::invalid_argument("concatenation: " + std::to_string(result.states.size()) +
                                " selected states for " + std::to_string(targets.size()) + " target phones");
  if (targets.empty()) return Eigen::MatrixXf(0, pca_frames.cols());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    if (targets[t].end_frame <= targets[t].first_frame)
      throw std::invalid_argument("concatenation: target phone " + std::to_string(t) + " spans no frames");
    if (t > 0 && targets[t].first_frame != targets[t - 1].end_frame)
      throw std::invalid_argument("concatenation: target phone " + std::to_string(t) +
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
  const auto frames = static_cast<std::size_t>(targets.back().end_frame - origin);
  const auto k = static_cast<std::size_t>(pca_frames.cols());
  std::vector<double> weights(frames, 1.0);
  for (const TargetPhone& target : targets)
    if (target.hold)
      std::fill(weights.begin() + (target.first_frame - origin), weights.begin() + (target.end_frame - origin),
                options.hold_weight);

  // What a frame shows: a state warped onto a target phone's span, read from the recording of
  // the target `recording` (a state's parent shares its recording). Piece t is target t's own.
  struct Piece {
    StateId state;
    std::size_t recording;
    std::int64_t first, end;
  };
  std::vector<Piece> pieces;
  pieces.reserve(targets.size() + result.units.size());
  for (std::size_t t = 0; t < targets.size(); ++t)
    pieces.push_back({result.states[t], t, targets[t].first_frame, targets[t].end_frame});
  std::vector<std::uint32_t> shown(frames);  // the piece of each frame outside cross-fades
  for (std::size_t t = 0; t < targets.size(); ++t)
    std::fill(shown.begin() + (targets[t].first_frame - origin), shown.begin() + (targets[t].end_frame - origin),
              static_cast<std::uint32_t>(t));

  // Hand-over at each join: the unit that ends runs on into its own recording, the one that
  // starts runs back into its own, and a raised cosine hands one over to the other. Mid-phone,
  // the new unit stands in for the second half of target t - 1 with its state's parent (which
  // the join rule makes of that phone's class) and the hand-over is centred there. fade_from[n],
  // fade_to[n]: the pieces frame n fades between (kNoFade: none; a later join wins where two
  // windows meet), fade_weight[n] the weight of the second.
  constexpr std::uint32_t kNoFade = std::numeric_limits<std::uint32_t>::max();
  const int h = std::max(0, options.blend_half_width);
  std::vector<std::uint32_t> fade_from(frames, kNoFade), fade_to(frames, kNoFade);
  std::vector<float> fade_weight(frames, 0.0f);
  std::vector<float> ramp;  // the raised cosine over a window of ramp.size() frames (most are 2h)
  for (std::size_t u = 1; u < result.units.size(); ++u) {
    const std::size_t t = result.units[u].first_target;  // first phone of the new unit
    const StateId j = result.states[t];
    const TargetPhone& before = targets[t - 1];
    const bool mid = options.join_mid_phone && graph.has_parent(j) &&
                     graph.state(j - 1).viseme == graph.state(result.states[t - 1]).viseme;
    auto incoming = static_cast<std::uint32_t>(t);
    std::int64_t join = targets[t].first_frame, window_end = targets[t].end_frame;
    if (mid) {
      incoming = static_cast<std::uint32_t>(pieces.size());
      pieces.push_back({j - 1, t, before.first_frame, before.end_frame});
      join = before.first_frame + (before.end_frame - before.first_frame) / 2;
      window_end = before.end_frame;
      std::fill(shown.begin() + (join - origin), shown.begin() + (before.end_frame - origin), incoming);
    }
    if (h == 0) continue;
    const std::int64_t lo = std::max(join - h, before.first_frame);
    const std::int64_t hi = std::min(join + h, window_end);
    if (ramp.size() != static_cast<std::size_t>(hi - lo)) {
      ramp.resize(static_cast<std::size_t>(hi - lo));
      for (std::size_t r = 0; r < ramp.size(); ++r) {
        const double x = (static_cast<double>(r) + 0.5) / static_cast<double>(hi - lo);
        ramp[r] = static_cast<float>(0.5 - 0.5 * std::cos(std::numbers::pi * x));
      }
    }
    for (std::int64_t n = lo; n < hi; ++n) {
      const auto i = static_cast<std::size_t>(n - origin);
      fade_from[i] = static_cast<std::uint32_t>(t - 1);
      fade_to[i] = incoming;
      fade_weight[i] = ramp[static_cast<std::size_t>(n - lo)];
    }
  }

  auto tap_of = [&](const Piece& p, std::int64_t n) {
    return tap(recordings[p.recording], warp(graph.state(p.state).frames, p.first, p.end, n));
  };
  auto value = [&](Tap a, std::size_t c) {
    const auto col = static_cast<Eigen::Index>(c);
    return (1.0f - a.f) * pca_frames(a.i0, col) + a.f * pca_frames(a.i1, col);
  };
  // The frames, row-major in double: what the smoother works on, a frame at a time.
  const bool smooth = options.smoothing > 0.0 && frames >= 3;
  const SmoothingFactor factor = smooth ? factor_smoother(weights, options.smoothing) : SmoothingFactor{};
  Eigen::VectorXd z(static_cast<Eigen::Index>(frames * k));
  Eigen::MatrixXf out(static_cast<Eigen::Index>(frames), static_cast<Eigen::Index>(k));
  for (std::size_t i = 0; i < frames; ++i) {
    const auto n = origin + static_cast<std::int64_t>(i);
    double* row = z.data() + i * k;
    if (fade_from[i] != kNoFade) {
      const Tap a = tap_of(pieces[fade_from[i]], n), b = tap_of(pieces[fade_to[i]], n);
      const float w = fade_weight[i];
      for (std::size_t c = 0; c < k; ++c) row[c] = (1.0f - w) * value(a, c) + w * value(b, c);
    } else {
      const Tap a = tap_of(pieces[shown[i]], n);
      for (std::size_t c = 0; c < k; ++c) row[c] = value(a, c);
    }
    if (!smooth) {
      for (std::size_t c = 0; c < k; ++c)
        out(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)) = static_cast<float>(row[c]);
      continue;
    }
    forward_substitute(factor, weights, i, z.data(), k);
  }
  if (smooth) backward_substitute(factor, z.data(), k, out);
  return out;
}

Eigen::MatrixXf smooth_trajectory(const Eigen::MatrixXf& x, std::span<const double> weights,
                                  double lambda) {
  const auto n = static_cast<std::size_t>(x.rows());
  if (weights.size() != n) throw std::invalid_argument("smooth: one weight per frame expected");
  if (n < 3 || lambda <= 0.0) return x;
  // (W + lambda D'D) y = W x: a discrete smoothing spline.
  const SmoothingFactor factor = factor_smoother(weights, lambda);
  const auto k = static_cast<std::size_t>(x.cols());
  Eigen::VectorXd z(static_cast<Eigen::Index>(n * k));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < k; ++c)
      z.data()[i * k + c] = static_cast<double>(x(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)));
    forward_substitute(factor, weights, i, z.data(), k);
  }
  Eigen::MatrixXf y(x.rows(), x.cols());
  backward_substitute(factor, z.data(), k, y);
  return y;
}

}  // namespace fapcast
