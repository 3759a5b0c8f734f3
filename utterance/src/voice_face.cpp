#include "fapcast/utterance/voice_face.hpp"

#include "fapcast/phonetics/viseme.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace fapcast {

FeaturePointBasis face_basis(const SpeechBasis& basis, const Voice& voice,
                                    const std::string& source) {
  std::vector<FeaturePointVertex> vertices;
  FeaturePointPositions neutral;
  for (const VoiceFeaturePoint& p : voice.feature_points()) {
    const auto fp = parse_feature_point(p.label);
    if (!fp) throw std::runtime_error(source + ": feature point label '" + p.label + "' is not an MPEG-4 feature point");
    vertices.push_back({*fp, p.vertex});
    neutral[*fp] = p.neutral_m;
  }
  // The PCA components in place in the voice's file, then the added directions: only the
  // points' columns are read.
  FeaturePointBasis b = restrict_basis(basis.mean(), basis.pca_components(), vertices, std::move(neutral));
  if (basis.added().rows() > 0) {
    const FeaturePointBasis added = restrict_basis(basis.mean(), basis.added(), vertices, b.neutral);
    b.components.conservativeResize(basis.size(), Eigen::NoChange);
    b.components.bottomRows(basis.added().rows()) = added.components;
  }
  return b;
}

void check_voice_phone_set(const Voice& voice, const std::string& source) {
  const auto phones = voice.state_phones();
  if (phones.size() != voice.graph().size())
    throw std::runtime_error(source + ": voice-phone-set: " + std::to_string(phones.size()) + " state phones for " +
                             std::to_string(voice.graph().size()) + " graph states");
  for (std::size_t j = 0; j < phones.size(); ++j) {
    const VisemeClass here = search_viseme(phones[j]);
    const VisemeClass there = voice.graph().state(static_cast<StateId>(j)).viseme;
    if (here != there)
      throw std::runtime_error(source + ": voice-phone-set: state " + std::to_string(j) + " ('" +
                               std::string(arpabet(phones[j])) + "') is of class " +
                               std::string(viseme_class_name(there)) + " in the voice but " +
                               std::string(viseme_class_name(here)) +
                               " here: the voice was built with another phone set or viseme table");
  }
}
}  // namespace fapcast
