#pragma once
// What `say` and `animate` take from a voice: its search data and its face basis restricted to
// the feature points (codec's input type), and the default voice when none is named.
#include "fapcast/codec/feature_point_basis.hpp"
#include "fapcast/synthesis/speech_expression.hpp"
#include "fapcast/voice/voice.hpp"

#include <filesystem>
#include <string>

namespace fapcast::cli {

// `basis` (the voice's PCA basis, with an expression when one is asked for; metres) at the
// voice's feature points' vertices, with their neutral positions. Throws std::runtime_error
// naming the voice and the label when a label is not a feature point.
FeaturePointBasis face_basis(const SpeechBasis& basis, const Voice& voice,
                                    const std::string& source);

// Checks that the voice's graph classes are this build's classes of its phones (a voice built
// with another phone set or viseme table would search the wrong units). Throws
// std::runtime_error "SOURCE: voice-phone-set: ..." naming the first state that disagrees.
void check_voice_phone_set(const Voice& voice, const std::string& source);

// Opens `path`, or the default voice (built on first use) when it is empty.
Voice open_voice_or_default(const std::filesystem::path& path, bool quiet);

}  // namespace fapcast::cli
