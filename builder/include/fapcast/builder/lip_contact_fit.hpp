#pragma once
// The lip-contact term of a corpus's retargeting (voice/lip_contact.hpp, spec/voice.md "Lip
// contact"), measured on the corpus and the target face at build time.
#include <Eigen/Core>

#include <optional>
#include <span>
#include <string_view>

#include "fapcast/face/face_model.hpp"
#include "fapcast/select/phone_graph.hpp"
#include "fapcast/voice/lip_contact.hpp"

namespace fapcast {

// How far above contact a source's inner lips may be for the term to act: 2 mm, about twice the
// scatter of the reference corpus's closures (their smallest distances span 0.3-1.6 mm) and well
// under a lax vowel's opening, so the map's own opening of every open frame is left alone.
inline constexpr double kLipContactReachM = 0.002;

// How the term is made (recorded in every voice's provenance that has it).
inline constexpr std::string_view kLipContactRule =
    "where the source's inner lips (2.2-2.3) are within 2 mm of their contact (the median over P B M "
    "states of each one's least distance), ICT mouthClose is added until the target's inner lips are no "
    "further above their contact (the bilabial target prototype's gap) than the source's (at most 1.5 units, "
    "faded out over the second mm)";

// The term of `map` for source frames `source` (d x F, metres, in source_marker_rows() order) whose phone
// states are `states` (frames index `source`'s columns): the closing shape is the face's mouthClose;
// the source's contact distance is the median over the bilabial states (P B M) of each state's
// smallest 2.2 - 2.3 distance; the target's contact gap is that of `bilabial_target` (the bilabial
// target prototype, D = 3N metres). nullopt when no state is bilabial.
std::optional<LipContact> fit_lip_contact(const FaceModel& face, const RbfMap& map, const Eigen::MatrixXd& source,
                                          std::span<const PhoneState> states,
                                          const Eigen::Ref<const Eigen::VectorXd>& bilabial_target);

}  // namespace fapcast
