#pragma once
// What the reference-talker tests share: one actor, a word as a script item, and how far apart
// two takes' markers are.
#include "fapcast/talker/reference_talker.hpp"

#include "fapcast/face/face_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

namespace fapcast::test {

// A common word of the recording script.
inline ScriptItem script_word(const std::string& text) {
  return {ScriptSection::kCommonWord, text, {}, "", 0.0};
}

// The reference actor of seed 7 on the generic ICT face, made once.
inline const FaceModel& test_actor() {
  static const FaceModel actor = reference_actor(ict_face_model(), 7);
  return actor;
}

// RMS (cm) of the difference between two takes over the frames both have and the samples present
// in both (takes of other seeds differ in speaking rate, so their lengths may differ); `samples`,
// when given, receives how many samples were compared.
inline double rms_difference(const MarkerFrames<Centimetres>& a, const MarkerFrames<Centimetres>& b,
                             std::size_t* samples = nullptr) {
  double sum = 0;
  std::size_t n = 0;
  for (Eigen::Index k = 0; k < std::min(a.frame_count(), b.frame_count()); ++k)
    for (Eigen::Index m = 0; m < a.marker_count(); ++m)
      if (a.present(m, k) && b.present(m, k)) {
        sum += (a.at(m, k) - b.at(m, k)).squaredNorm();
        ++n;
      }
  if (samples != nullptr) *samples = n;
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

}  // namespace fapcast::test
