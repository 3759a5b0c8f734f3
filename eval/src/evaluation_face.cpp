// Kept apart from synthesis_evaluation.cpp: this is the one place the evaluation reads a Voice
// and the voice build's corpus rules (voice_corpus.hpp).
#include "fapcast/face/marker_map.hpp"
#include "fapcast/capture/preprocessing.hpp"
#include "fapcast/eval/synthesis_evaluation.hpp"
#include "fapcast/voice/voice.hpp"
#include "fapcast/builder/voice_corpus.hpp"
#include "fapcast/talker/reference_talker.hpp"

#include <cmath>
#include <stdexcept>

namespace fapcast {

EvaluationFace evaluation_face(const Voice& voice) {
  std::vector<std::string> labels;
  std::vector<std::int32_t> vertices;
  for (const auto& p : voice.feature_points()) labels.push_back(p.label), vertices.push_back(p.vertex);
  const auto sites = marker_sites();
  const auto rigid_rows = rigid_marker_rows();
  // The voice's source head frame in rigid_marker_rows() order, cm (what preprocess_take wants),
  // and the temples' target vertices.
  Eigen::Matrix3Xd reference(3, static_cast<Eigen::Index>(rigid_rows.size()));
  std::array<std::int32_t, 2> temples{-1, -1};
  for (std::size_t i = 0; i < rigid_rows.size(); ++i) {
    bool found = false;
    for (const auto& r : voice.rigid_markers()) {
      if (r.label != sites[rigid_rows[i]].label) continue;
      reference.col(static_cast<Eigen::Index>(i)) = 100.0 * r.source_reference_m;
      if (r.label == "H.temple_l") temples[0] = r.vertex;
      if (r.label == "H.temple_r") temples[1] = r.vertex;
      found = true;
    }
    if (!found)
      throw std::runtime_error(voice.file().source() + ": the voice has no rigid marker " +
                               std::string(sites[rigid_rows[i]].label));
  }
  if (temples[0] < 0 || temples[1] < 0)
    throw std::runtime_error(voice.file().source() + ": the voice has no temple markers for lip protrusion");
  return {voice.pca_mean(), voice.pca_components(), &voice.retargeting(),
          [reference](const MarkerFrames<Centimetres>& take) {
            return source_vectors_m(preprocess_take(take, rigid_marker_rows(), reference).frames, "held-out take");
          },
          evaluation_points(labels, vertices, temples)};
}

FaceModel held_out_actor(const Voice& voice) {
  const auto& provenance = voice.provenance();
  const std::string file = voice.file().source();
  if (!provenance.synthetic)
    throw std::runtime_error(file + ": held-out takes are recorded by the reference talker, so the voice must be "
                             "built from a reference corpus (provenance synthetic), and this one is not");
  const auto seed = provenance.parameters.find("corpus_seed");
  if (seed == provenance.parameters.end())
    throw std::runtime_error(file + ": the voice does not say which reference corpus it was built from (no "
                             "provenance parameter corpus_seed: its corpus had no manifest seed), so the actor "
                             "to record held-out takes with is unknown");
  // Seeds are written as JSON numbers (doubles): whole and exactly representable below 2^53.
  const double value = seed->second;
  if (!(value >= 0.0 && value < 9007199254740992.0 && std::floor(value) == value))
    throw std::runtime_error(file + ": provenance parameter corpus_seed " + std::to_string(value) +
                             " is not a whole number from 0 to 2^53");
  return reference_actor(ict_face_model(), static_cast<std::uint64_t>(value));
}

}  // namespace fapcast
