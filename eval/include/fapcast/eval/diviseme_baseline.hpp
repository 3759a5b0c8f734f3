#pragma once
// Evaluation baseline: diviseme-only concatenation, the paper's System B (Ma et al. 2006,
// section 4). Every unit is exactly one diviseme - two consecutive target phones - cut from a
// corpus recording of that viseme pair, from the centre of its first phone to the centre of its
// second; consecutive divisemes meet in the middle of the phone they share (the classic diviseme
// cut, where a phone is most stable). The units go through concatenate_units - the same time warp,
// cross-fade and smoothing as the variable-length search's units - so only the unit choice
// differs between the two systems.
#include "fapcast/select/phone_graph.hpp"
#include "fapcast/synthesis/unit_concatenation.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <span>
#include <vector>

namespace fapcast {

// The corpus instance chosen for the diviseme of target phones (t, t + 1).
struct DivisemeChoice {
  StateId first_state = 0;   // of target t's viseme class
  StateId second_state = 0;  // of target t + 1's class; first_state + 1 when `recorded`
  // False when the corpus never recorded this viseme pair: the two halves then come from the
  // best-matching single phones of each class and meet at the phone boundary (a hard join).
  bool recorded = true;
  bool operator==(const DivisemeChoice&) const = default;
};

struct DivisemeSelection {
  std::vector<DivisemeChoice> divisemes;  // one per pair of consecutive targets: T - 1
  std::size_t unrecorded = 0;             // divisemes with recorded == false
};

// How an instance of a diviseme is chosen among its recordings.
enum class DivisemeChoiceRule {
  kBestDuration,  // the least sum over its two phones of (log(recorded / target frames))^2
  kFirst,         // the first recorded (lowest state id): no regard to timing (an ablation)
};

// Chooses, for every pair of consecutive targets, a recorded instance of that viseme pair by
// `rule`; ties go to the lowest state id (deterministic).
// Throws std::invalid_argument when there are fewer than two targets, a target spans no frames,
// or a target viseme class has no state at all (naming the class and the target position).
DivisemeSelection select_divisemes(const PhoneGraph& graph, std::span<const TargetPhone> targets,
                                   DivisemeChoiceRule rule = DivisemeChoiceRule::kBestDuration);

// Concatenates a selection over `targets` from the voice's PCA frames (frames x k): each target phone
// is cut at its middle frame into two halves (a one-frame phone stays whole, in its first half);
// the first half comes from the diviseme ending in the phone, the second from the diviseme
// starting there (the very first and last halves from the first and last divisemes). Returns
// end_frame(last) - first_frame(first) rows of k, like concatenate_units. Throws
// std::invalid_argument when the selection does not fit the targets.
Eigen::MatrixXf concatenate_divisemes(const PhoneGraph& graph, const PcaFrames& pca_frames,
                                 const DivisemeSelection& selection,
                                 std::span<const TargetPhone> targets,
                                 const ConcatenationOptions& options = {});

}  // namespace fapcast
