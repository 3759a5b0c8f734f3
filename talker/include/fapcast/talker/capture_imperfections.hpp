#pragma once
// The imperfections of real capture, applied to the reference talker's clean markers (SYNTHETIC):
// per utterance speaking-rate and effort variation; per take smooth head motion, marker noise
// and dropped-marker runs. All draws come from a PortableRandom, so a seed reproduces a take.
#include <Eigen/Core>
#include <vector>

#include "fapcast/corpus/marker_frames.hpp"
#include "fapcast/core/portable_random.hpp"
#include "fapcast/math/rigid_transform.hpp"

namespace fapcast {

// How this utterance is spoken. rate_factor multiplies the TTS speaking rate (1.1 = 10 % faster;
// pass it to the front-end so audio and motion agree); effort scales articulation targets
// (CoarticulationOptions::effort).
struct UtteranceVariation {
  double rate_factor = 1.0;  // uniform in [0.88, 1.12]
  float effort = 1.0f;       // uniform in [0.85, 1.15]
};
UtteranceVariation draw_utterance_variation(PortableRandom& random);

// Smooth head motion: each rotation angle and translation axis is a sum of two sinusoids of
// random frequency (0.05-0.6 Hz) and phase; rotation about a neck pivot below the head.
struct HeadMotionLimits {
  double max_rotation_deg = 3.0;     // per axis, peak
  double max_translation_mm = 3.0;   // per axis, peak
  Eigen::Vector3d pivot_cm{0.0, -12.0, 0.0};  // rotation centre (ICT frame: below the jaw, neck)
};
class HeadMotion {
 public:
  HeadMotion(PortableRandom& random, const HeadMotionLimits& limits = {});
  // The head's rigid motion at t_s seconds (head frame -> capture frame).
  RigidTransform at(double t_s) const;

 private:
  struct Wave {
    double amplitude, frequency_hz, phase;
  };
  std::array<std::array<Wave, 2>, 6> waves_;  // yaw, pitch, roll (rad), x, y, z (cm)
  Eigen::Vector3d pivot_cm_;
};

// Moves every present marker of every frame by the head motion at the frame's time.
void apply_head_motion(MarkerFrames<Centimetres>& frames, const HeadMotion& motion);

// Adds isotropic Gaussian noise of sigma_mm per coordinate to every present sample.
void add_marker_noise(MarkerFrames<Centimetres>& frames, PortableRandom& random, double sigma_mm = 0.2);

struct DropoutLimits {
  double runs_per_marker_minute = 3.0;  // expected dropped runs per marker per minute
  Eigen::Index max_run_frames = 6;      // run length uniform in [1, max_run_frames]
};
struct DroppedRun {
  Eigen::Index marker, first_frame, frame_count;
};
// Drops runs of frames of random markers (occlusions); returns what it dropped.
std::vector<DroppedRun> drop_marker_runs(MarkerFrames<Centimetres>& frames, PortableRandom& random,
                                         const DropoutLimits& limits = {});

// All per-take imperfections, in capture order: head motion, noise, dropouts.
struct CaptureSettings {
  HeadMotionLimits head_motion{};
  double noise_sigma_mm = 0.2;
  DropoutLimits dropouts{};
};
struct CapturedTake {
  MarkerFrames<Centimetres> frames;              // what the "studio" delivers
  std::vector<DroppedRun> dropped;  // ground truth of the dropouts
};
// Applies every imperfection to a clean take; the same random state gives the same take.
CapturedTake capture_take(const MarkerFrames<Centimetres>& clean, PortableRandom& random,
                          const CaptureSettings& settings = {});

}  // namespace fapcast
