#include "fapcast/talker/capture_imperfections.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace fapcast {

UtteranceVariation draw_utterance_variation(PortableRandom& random) {
  UtteranceVariation v;
  v.rate_factor = random.uniform(0.88, 1.12);
  v.effort = static_cast<float>(random.uniform(0.85, 1.15));
  return v;
}

HeadMotion::HeadMotion(PortableRandom& random, const HeadMotionLimits& limits)
    : pivot_cm_(limits.pivot_cm) {
  for (std::size_t axis = 0; axis < waves_.size(); ++axis) {
    const double peak = axis < 3 ? limits.max_rotation_deg * std::numbers::pi / 180.0
                                 : limits.max_translation_mm / 10.0;
    for (auto& wave : waves_[axis]) {
      // Two waves whose amplitudes sum to at most the peak.
      wave.amplitude = random.uniform(0.0, 0.5 * peak);
      wave.frequency_hz = random.uniform(0.05, 0.6);
      wave.phase = random.uniform(0.0, 2.0 * std::numbers::pi);
    }
  }
}

RigidTransform HeadMotion::at(double t_s) const {
  std::array<double, 6> v{};
  for (std::size_t axis = 0; axis < waves_.size(); ++axis)
    for (const auto& w : waves_[axis])
      v[axis] += w.amplitude * std::sin(2.0 * std::numbers::pi * w.frequency_hz * t_s + w.phase);
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(v[0], Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(v[1], Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(v[2], Eigen::Vector3d::UnitZ()))
                                .toRotationMatrix();
  RigidTransform t;
  t.rotation = r;
  t.translation = pivot_cm_ - r * pivot_cm_ + Eigen::Vector3d(v[3], v[4], v[5]);
  return t;
}

void apply_head_motion(MarkerFrames<Centimetres>& frames, const HeadMotion& motion) {
  for (Eigen::Index k = 0; k < frames.frame_count(); ++k) {
    const RigidTransform pose = motion.at(static_cast<double>(k) / frames.frame_rate_hz);
    for (Eigen::Index m = 0; m < frames.marker_count(); ++m)
      if (frames.present(m, k)) frames.positions.block<3, 1>(3 * m, k) = pose.apply(frames.at(m, k));
  }
}

void add_marker_noise(MarkerFrames<Centimetres>& frames, PortableRandom& random, double sigma_mm) {
  const double sigma_cm = sigma_mm / 10.0;
  for (Eigen::Index k = 0; k < frames.frame_count(); ++k)
    for (Eigen::Index m = 0; m < frames.marker_count(); ++m) {
      if (!frames.present(m, k)) continue;
      for (Eigen::Index c = 0; c < 3; ++c) frames.positions(3 * m + c, k) += sigma_cm * random.normal();
    }
}

std::vector<DroppedRun> drop_marker_runs(MarkerFrames<Centimetres>& frames, PortableRandom& random,
                                         const DropoutLimits& limits) {
  std::vector<DroppedRun> runs;
  if (frames.frame_count() == 0 || limits.max_run_frames < 1) return runs;
  // Per marker, run starts form a Bernoulli process with this probability per frame.
  const double per_frame = limits.runs_per_marker_minute / (60.0 * frames.frame_rate_hz);
  for (Eigen::Index m = 0; m < frames.marker_count(); ++m) {
    for (Eigen::Index k = 0; k < frames.frame_count(); ++k) {
      if (random.uniform() >= per_frame) continue;
      const auto length = static_cast<Eigen::Index>(
          1 + random.below(static_cast<std::uint64_t>(limits.max_run_frames)));
      const Eigen::Index end = std::min(frames.frame_count(), k + length);
      for (Eigen::Index f = k; f < end; ++f) frames.drop(m, f);
      runs.push_back({m, k, end - k});
      k = end;  // the next run starts after this one (and at least one present frame)
    }
  }
  return runs;
}

CapturedTake capture_take(const MarkerFrames<Centimetres>& clean, PortableRandom& random,
                          const CaptureSettings& settings) {
  CapturedTake take{clean, {}};
  apply_head_motion(take.frames, HeadMotion(random, settings.head_motion));
  add_marker_noise(take.frames, random, settings.noise_sigma_mm);
  take.dropped = drop_marker_runs(take.frames, random, settings.dropouts);
  return take;
}

}  // namespace fapcast
