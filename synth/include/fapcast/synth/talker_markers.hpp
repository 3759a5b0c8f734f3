#pragma once
// The reference talker's clean marker trajectories (SYNTHETIC): phone timeline -> channel tracks
// -> ICT expression weights -> marker positions on the actor's face.
#include <Eigen/Core>

#include "fapcast/synth/coarticulation.hpp"
#include "fapcast/synth/face_model.hpp"
#include "fapcast/synth/marker_frames.hpp"
#include "fapcast/synth/marker_map.hpp"

namespace fapcast::synth {

// Marker positions for per-frame expression weights (shapes x frames), labelled by the table.
MarkerFrames render_markers(const MarkerBlender& blender, const Eigen::MatrixXf& weights,
                            std::int32_t frame_rate_hz);

// The whole clean chain for one utterance on one face, all markers of marker_sites().
MarkerFrames talker_markers(const FaceModel& face, const PhoneTimeline& timeline,
                            const CoarticulationOptions& options = {});

}  // namespace fapcast::synth
