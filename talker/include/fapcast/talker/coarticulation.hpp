#pragma once
// Cohen & Massaro (1993) coarticulation: a phone timeline becomes articulatory channel tracks.
// Per channel, F(t) = sum_s D_s(t - centre_s) T_s / sum_s D_s(t - centre_s) over all phones s.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "fapcast/core/sample_rate.hpp"
#include "fapcast/phonetics/timed_phone.hpp"
#include "fapcast/talker/articulation.hpp"

namespace fapcast {

struct PhoneTimeline {
  SampleRate sample_rate;  // valid
  std::vector<TimedPhone> phones;  // in time order, non-overlapping, each non-empty
};

struct CoarticulationOptions {
  std::int32_t frame_rate_hz = 60;  // frames at t = k / frame_rate_hz seconds, k = 0, 1, ...
  float effort = 1.0f;  // scales the jaw, lip-opening, rounding and spreading targets (hypo/hyper)
};

// One column per frame, one row per Channel; every value in [0, 1].
struct ChannelTracks {
  std::int32_t frame_rate_hz = 60;
  Eigen::Matrix<float, static_cast<int>(kChannelCount), Eigen::Dynamic> values;
  Eigen::Index frame_count() const { return values.cols(); }
  // Channel values of one frame.
  std::array<float, kChannelCount> frame(Eigen::Index k) const;
};

// Checks a timeline (rate > 0, spans non-empty, ordered, non-overlapping, phones known); throws
// std::invalid_argument naming the offending phone index.
void validate_timeline(const PhoneTimeline& timeline);

// Channel values at time t_s seconds (the dominance-weighted mean of the phones' targets);
// validates the timeline like coarticulate().
std::array<float, kChannelCount> channel_values_at(const PhoneTimeline& timeline, double t_s,
                                                   float effort = 1.0f);

// Channel tracks covering the timeline: ceil(end * fps / rate) frames.
ChannelTracks coarticulate(const PhoneTimeline& timeline, const CoarticulationOptions& options = {});

// Expression-shape weights per frame: shape_count x frames, each in [0, 1].
Eigen::MatrixXf expression_weights(const ChannelTracks& tracks, const ShapeMapper& mapper);

}  // namespace fapcast
