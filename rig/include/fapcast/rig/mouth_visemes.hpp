#pragma once
// Oculus/Meta's 15 visemes and VRM's five vowels from the phones and the fitted ARKit shapes
// (spec/rigs.md, "Visemes"). Each viseme has a prototype: the mean fitted ARKit vector at the centre
// frame of every corpus phone of that viseme (the voice's own mouth shapes). Per frame:
//  - Oculus: weights on the simplex (w >= 0, sum 1: OVRLipSync's values are probabilities),
//    among the visemes of the phones within `support_frames` and sil, minimising
//    |P w - a|_M^2 + prior * s * |w - e_phone|^2: the fitted face sets the mix, the phone on screen
//    its identity (prior 0 is the face alone, large the one-viseme-per-phone lookup);
//  - VRM: weights in [0, 1] on aa ih ou ee oh (neutral = closed lips) minimising |P w - a|_M^2.
// M is the face metric (ArkitFit::gram) with the inner-lip opening (2.2 - 2.3, vertical) weighted
// `gap_weight` x trace(H) / |gap row|^2 more, so apertures (open vowels, closed /p b m/) count.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "fapcast/phonetics/phone.hpp"

namespace fapcast {

class ArkitFit;
class Voice;

enum class OculusViseme : unsigned char { kSil, kPP, kFF, kTH, kDD, kKK, kCH, kSS, kNN, kRR, kAA, kE, kIH, kOH, kOU };
inline constexpr std::size_t kOculusVisemeCount = 15;
// OVRLipSync / OpenXR XR_META_face_tracking_visemes order and names.
inline constexpr std::array<std::string_view, kOculusVisemeCount> kOculusVisemeNames{
    "sil", "PP", "FF", "TH", "DD", "kk", "CH", "SS", "nn", "RR", "aa", "E", "ih", "oh", "ou"};
// The morph-target names Ready Player Me avatars carry and TalkingHead drives.
inline constexpr std::array<std::string_view, kOculusVisemeCount> kOculusMorphNames{
    "viseme_sil", "viseme_PP", "viseme_FF", "viseme_TH", "viseme_DD", "viseme_kk", "viseme_CH", "viseme_SS",
    "viseme_nn", "viseme_RR", "viseme_aa", "viseme_E", "viseme_I", "viseme_O", "viseme_U"};

// A phone's viseme (spec/rigs.md table); nullopt for HH, which takes the next phone's.
std::optional<OculusViseme> oculus_viseme(Phone phone);

// The viseme shown in each frame: oculus_viseme of the frame's phone, HH the next non-HH frame's
// (sil at the end).
std::vector<OculusViseme> oculus_viseme_timeline(std::span<const Phone> phone_per_frame);

enum class VrmVowel : unsigned char { kAa, kIh, kOu, kEe, kOh };
inline constexpr std::size_t kVrmVowelCount = 5;
inline constexpr std::array<std::string_view, kVrmVowelCount> kVrmVowelNames{"aa", "ih", "ou", "ee", "oh"};
// VRM 0.x BlendShapeClip preset names of the same vowels.
inline constexpr std::array<std::string_view, kVrmVowelCount> kVrm0VowelNames{"A", "I", "U", "E", "O"};
inline constexpr std::array<OculusViseme, kVrmVowelCount> kVrmVowelViseme{
    OculusViseme::kAA, OculusViseme::kIH, OculusViseme::kOU, OculusViseme::kE, OculusViseme::kOH};

struct VisemeOptions {
  double prior = 0.3;        // Oculus: weight of the phone's own viseme (see above)
  int support_frames = 6;    // Oculus: visemes of the phones within this many frames may mix
  double gap_weight = 10.0;  // the inner-lip opening's extra weight in the metric
};

class MouthVisemes {
 public:
  // Prototypes from the voice's corpus (every phone state's centre frame, fitted by `fit`).
  MouthVisemes(const ArkitFit& fit, const Voice& voice, const VisemeOptions& options = {});

  // frames x 15 (kOculusVisemeNames order); `arkit` is ArkitTrack::weights (frames x 52).
  Eigen::MatrixXf oculus(const Eigen::MatrixXf& arkit, std::span<const Phone> phone_per_frame) const;
  // frames x 5 (kVrmVowelNames order).
  Eigen::MatrixXf vrm(const Eigen::MatrixXf& arkit) const;

  // The prototypes over the fitted columns (ArkitFit::columns() x 15), and how many corpus phones
  // each is the mean of.
  const Eigen::MatrixXd& prototypes() const { return prototypes_; }
  const std::array<int, kOculusVisemeCount>& prototype_counts() const { return counts_; }
  // The metric M (fitted columns square).
  const Eigen::MatrixXd& metric() const { return metric_; }

 private:
  std::vector<int> columns_;
  Eigen::MatrixXd prototypes_, metric_;
  Eigen::MatrixXd oculus_q_, oculus_pm_;  // 15 x 15 P'MP, 15 x n P'M
  Eigen::MatrixXd vrm_q_, vrm_pm_;
  std::array<int, kOculusVisemeCount> counts_{};
  VisemeOptions options_;
  double oculus_scale_ = 1.0;
};

}  // namespace fapcast
