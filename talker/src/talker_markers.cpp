#include "fapcast/talker/talker_markers.hpp"

#include <stdexcept>

namespace fapcast {

MarkerFrames<Centimetres> blend_markers(const MarkerBlender& blender, const Eigen::MatrixXf& weights,
                            std::int32_t frame_rate_hz) {
  const auto sites = marker_sites();
  if (blender.marker_count() != sites.size())
    throw std::invalid_argument("blend_markers: blender has " +
                                std::to_string(blender.marker_count()) + " markers, table " +
                                std::to_string(sites.size()));
  MarkerFrames<Centimetres> out;
  for (const auto& s : sites) out.labels.emplace_back(s.label);
  out.frame_rate_hz = frame_rate_hz;
  out.positions.resize(3 * static_cast<Eigen::Index>(sites.size()), weights.cols());
  for (Eigen::Index k = 0; k < weights.cols(); ++k) {
    const Eigen::VectorXf w = weights.col(k);
    const Positions p = blender(std::span<const float>(w.data(), static_cast<std::size_t>(w.size())));
    out.positions.col(k) = Eigen::Map<const Eigen::VectorXf>(p.data(), p.size()).cast<double>();
  }
  return out;
}

MarkerFrames<Centimetres> talker_markers(const FaceModel& face, const PhoneTimeline& timeline,
                            const CoarticulationOptions& options) {
  const auto vertices = marker_vertices();
  const MarkerBlender blender(face, vertices);
  const ShapeMapper mapper(face);
  const ChannelTracks tracks = coarticulate(timeline, options);
  return blend_markers(blender, expression_weights(tracks, mapper), tracks.frame_rate_hz);
}

}  // namespace fapcast
