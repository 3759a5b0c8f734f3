#pragma once
// Live Link Face CSV, as Epic's Live Link Face app exports a take (spec/rigs.md, "Live Link Face
// CSV"): a header `Timecode,BlendShapeCount,` + the 52 ARKit names with an upper-case first letter in
// ARKit order + the 9 head and eye rotations; one row per frame: the timecode HH:MM:SS:FF.mmm (FF at
// 60 per second, .mmm the sub-frame in thousandths), 61, then the 61 values with 10 decimals
// (rotations 0: speech moves neither head nor eyes). LF line ends.
#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "fapcast/core/frame_rate.hpp"

namespace fapcast {

// `arkit`: frames x 52 (kArkitShapes order); frame f is at f / rate seconds. Throws
// std::invalid_argument for an invalid rate or a matrix that is not frames x 52.
std::string live_link_csv(const Eigen::MatrixXf& arkit, FrameRate rate);

// The timecode of frame f >= 0 at that rate: "HH:MM:SS:FF.mmm" (hours wrap at 24, as the app's);
// the thousandths of a timecode frame are frame_to_sample(f, rate, 60,000), the timeline's one rule.
std::string live_link_timecode(std::int64_t frame, FrameRate rate);

}  // namespace fapcast
