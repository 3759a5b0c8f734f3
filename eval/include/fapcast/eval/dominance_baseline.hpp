#pragma once
// Evaluation baseline: dominance-model interpolation of viseme targets (Cohen & Massaro 1993).
// Each viseme class gets one PCA target, the mean coefficients of the centre frames of that
// class's recorded phones; a target phone string becomes a trajectory by the dominance-weighted
// mean F(t) = sum_s D_s(t - centre_s) T_s / sum_s D_s(t - centre_s), D from articulation.hpp.
// This is the classic rule-based alternative to concatenation: no recorded motion, only targets.
#include "fapcast/math/dominance.hpp"
#include "fapcast/select/phone_graph.hpp"
#include "fapcast/synthesis/unit_concatenation.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace fapcast {

struct VisemeTargets {
  Eigen::MatrixXf coefficients;        // kVisemeClassCount x k, one target per class
  std::vector<std::uint32_t> phones;   // per class: recorded phones averaged (0 = none: no target)
};

// The mean PCA coefficients (pca_frames is frames x k) of the centre frame of every state of
// each class; a class with no state has a zero row and phones = 0.
VisemeTargets viseme_targets(const PhoneGraph& graph, const PcaFrames& pca_frames);

// Dominance functions per class. Generic, a priori values in the spirit of Cohen-Massaro, NOT the
// reference talker's table (spec/articulation.tsv): the baseline must not know the generator it
// is scored against. Contact classes (bilabial, labiodental) dominate so their contact is met.
struct DominanceBaselineOptions {
  Dominance phone{1.0f, 14.0f, 14.0f, 1.0f};     // every class not listed below
  Dominance contact{20.0f, 40.0f, 40.0f, 1.0f};  // kBilabial, kLabiodental
  Dominance silence{0.5f, 20.0f, 20.0f, 1.0f};   // kSilence
  int frame_rate_hz = 60;                        // the targets' frame grid
};

// The dominance of a class under `options`.
const Dominance& baseline_dominance(VisemeClass v, const DominanceBaselineOptions& options);

// Frames [first_frame(first), end_frame(last)) of k coefficients: frame n (at n / fps seconds)
// is the dominance-weighted mean of the targets of all phones, each centred on the mean time of
// its frames. Throws std::invalid_argument when a target spans no frames, targets overlap or are out of
// order, or a target's class has no recorded phone (naming it).
Eigen::MatrixXf dominance_interpolation(const VisemeTargets& targets,
                                        std::span<const TargetPhone> phones,
                                        const DominanceBaselineOptions& options = {});

}  // namespace fapcast
