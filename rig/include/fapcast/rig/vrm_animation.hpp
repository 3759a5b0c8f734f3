#pragma once
// VRM Animation (.vrma, VRMC_vrm_animation 1.0; spec/rigs.md, "VRM"): expression tracks as glTF
// 2.0 binary. Each expression is a node named after it whose translation's x is the weight
// (y = z = 0), animated by one LINEAR sampler per expression over shared key times; the extension
// lists them as `expressions.preset` (aa ih ou ee oh ...) or `expressions.custom` (any other name,
// e.g. ARKit's for perfect-sync models). A humanoid hips node at y = 1 m (the VRM T-pose), not
// animated, keeps players' T-pose check quiet. @pixiv/three-vrm-animation turns it into an
// AnimationClip of VRM expressions (createVRMAnimationClip).
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "fapcast/core/frame_rate.hpp"

namespace fapcast {

// `weights`: frames x names.size(); frame f is at f / rate seconds. Names that are VRM 1.0
// presets go to `preset`, others to `custom`. Throws std::invalid_argument for no frames, a shape
// mismatch, an empty or repeated name, or a zero rate.
std::string write_vrm_animation(std::span<const std::string> names, const Eigen::MatrixXf& weights,
                                FrameRate rate);

// Whether `name` is one of VRM 1.0's preset expressions.
bool is_vrm_preset_expression(std::string_view name);

}  // namespace fapcast
