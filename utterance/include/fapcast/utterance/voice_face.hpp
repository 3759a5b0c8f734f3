#pragma once
// What speaking takes from a voice: its face basis restricted to the feature points (codec's
// input type), and the check that the voice's phone set is this build's.
#include "fapcast/codec/feature_point_basis.hpp"
#include "fapcast/synthesis/speech_expression.hpp"
#include "fapcast/voice/voice.hpp"

#include <string>

namespace fapcast {

// `basis` (the voice's PCA basis, with an expression when one is asked for; metres) at the
// voice's feature points' vertices, with their neutral positions. Throws std::runtime_error
// naming the voice and the label when a label is not a feature point.
FeaturePointBasis face_basis(const SpeechBasis& basis, const Voice& voice, const std::string& source);

// Checks that the voice's graph classes are this build's classes of its phones (a voice built
// with another phone set or viseme table would search the wrong units). Throws
// std::runtime_error "SOURCE: voice-phone-set: ..." naming the first state that disagrees.
void check_voice_phone_set(const Voice& voice, const std::string& source);

}  // namespace fapcast
