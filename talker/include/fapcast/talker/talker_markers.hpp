#pragma once
// The reference talker's clean marker trajectories (SYNTHETIC): phone timeline -> channel tracks
// -> ICT expression weights -> marker positions on the actor's face.
#include <Eigen/Core>

#include "fapcast/talker/coarticulation.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/corpus/marker_frames.hpp"
#include "fapcast/face/marker_map.hpp"

namespace fapcast {

// Marker positions for per-frame expression weights (shapes x frames), labelled by the table.
MarkerFrames<Centimetres> blend_markers(const MarkerBlender& blender, const Eigen::MatrixXf& weights,
                            std::int32_t frame_rate_hz);

// The whole clean chain for one utterance on one face, all markers of marker_sites().
MarkerFrames<Centimetres> talker_markers(const FaceModel& face, const PhoneTimeline& timeline,
                            const CoarticulationOptions& options = {});

}  // namespace fapcast
