#pragma once
// The property of the voice fuzz targets: any bytes are refused with an InputError or give a
// voice whose parts can all be read (Voice::over_bytes over a copy aligned as a mapping is).
#include "fapcast/core/input_error.hpp"
#include "fapcast/voice/voice.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace fapcast::fuzz {

inline void read_every_part_of_voice(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint64_t> aligned(size / 8 + 1);  // a mapping is page-aligned; mimic it
  if (size > 0) std::memcpy(aligned.data(), data, size);
  try {
    const Voice voice = Voice::over_bytes({reinterpret_cast<const std::byte*>(aligned.data()), size}, "<fuzz>");
    double sum = voice.pca_mean().sum() + voice.pca_components().sum() + voice.pca_variances().sum() +
                 voice.frame_coefficients().sum();
    for (const VoiceFeaturePoint& p : voice.feature_points()) sum += p.neutral_m.sum() + p.vertex;
    for (const VoiceRigidMarker& r : voice.rigid_markers()) sum += r.source_reference_m.sum();
    for (std::size_t j = 0; j < voice.graph().size(); ++j) sum += voice.graph().state(static_cast<StateId>(j)).frames.count;
    if (const auto maps = voice.face_maps()) sum += maps->sum();
    (void)sum;
  } catch (const InputError&) {
  }
}

}  // namespace fapcast::fuzz
