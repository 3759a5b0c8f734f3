#pragma once
// The phone graph of the paper's section 3.7: one horizontal chain of phone states per recorded
// utterance, indexed so that the unit search never scans the corpus.
#include "fapcast/select/join_bound.hpp"
#include "fapcast/phonetics/viseme.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace fapcast {

using StateId = std::uint32_t;

// Frames [first, first + count) of the voice's frame array (60 fps).
struct FrameSpan {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  bool operator==(const FrameSpan&) const = default;
};

// A voice's PCA frames (frames x k), row-major as the voice file stores them, so the join
// features and the concatenation read them in place in the mapped file (a column-major matrix
// given here is copied first).
using PcaFrames = Eigen::Ref<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;

// One phone of one recorded utterance.
struct PhoneState {
  std::uint32_t utterance = 0;  // recordings are numbered 0..U-1
  VisemeClass viseme = VisemeClass::kSilence;
  FrameSpan frames;
  bool operator==(const PhoneState&) const = default;
};

// Boundary shape of a state for the join cost (see join_cost): `entry` is
// [x0, x1 - 2 x0] of its first two frames, `exit` is [2 x_-1 - x_-2, -x_-1] of its last two,
// where x are the PCA coefficient vectors (k each, so both have 2k entries). One row per state,
// row-major, zero-padded to a multiple of kJoinLanes columns: a state's boundary is one
// contiguous run of floats, and the padding adds nothing to any cost (zero in every row).
inline constexpr Eigen::Index kJoinLanes = 8;
using JoinRows = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
struct JoinFeatures {
  JoinRows entry;  // states x (2k rounded up to kJoinLanes)
  JoinRows exit;   // states x (2k rounded up to kJoinLanes)
};

// Makes the join features of every state from the voice's PCA frames (frames x k). A state
// shorter than two frames borrows frames from its neighbours in the recording.
JoinFeatures join_features(std::span<const PhoneState> states, const PcaFrames& pca_frames);

// C of a join from the state whose exit row is `exit` into the state whose entry row is `entry`
// (`dims` floats each, a multiple of kJoinLanes): half the squared distance of the rows, i.e.
// the mean squared second difference over the join. Summed in kJoinLanes fixed lanes, so
// every caller gets the same float to the bit; Dims > 0 fixes the width at compile time (the
// search's hot loop), Dims = 0 reads it from `dims`.
template <Eigen::Index Dims = 0>
inline float join_cost(const float* entry, const float* exit, Eigen::Index dims = Dims) {
  static_assert(kJoinLanes == 8 && Dims % kJoinLanes == 0, "two blocks of four lanes");
  using Four = Eigen::Array4f;
  const Eigen::Index width = Dims > 0 ? Dims : dims;
  Four low = Four::Zero(), high = Four::Zero();  // lanes 0-3 and 4-7
  for (Eigen::Index d = 0; d < width; d += kJoinLanes) {
    const Four g0 = Eigen::Map<const Four>(entry + d) - Eigen::Map<const Four>(exit + d);
    const Four g1 = Eigen::Map<const Four>(entry + d + 4) - Eigen::Map<const Four>(exit + d + 4);
    low += g0 * g0;
    high += g1 * g1;
  }
  const Four lane = low + high;  // lane l holds lanes l and l + 4
  return 0.5f * ((lane[0] + lane[2]) + (lane[1] + lane[3]));
}

class PhoneGraph {
 public:
  // `states` must list each utterance's phones contiguously and in spoken order; `features`
  // has one row per state (or is empty: then every join costs only its segment count).
  // Throws std::invalid_argument when a viseme class is out of range, an utterance's states
  // are not contiguous, or the feature rows do not match the states.
  PhoneGraph(std::vector<PhoneState> states, JoinFeatures features = {});

  std::size_t size() const { return states_.size(); }
  const PhoneState& state(StateId j) const { return states_[j]; }
  std::span<const PhoneState> states() const { return states_; }

  // The previous phone in the same recording, if any.
  bool has_parent(StateId j) const { return j > 0 && states_[j - 1].utterance == states_[j].utterance; }
  bool has_child(StateId i) const {
    return i + 1 < states_.size() && states_[i + 1].utterance == states_[i].utterance;
  }
  // The class of the next phone in the same recording, if any (one byte per state: the search
  // asks it of every active state at every phone).
  std::optional<VisemeClass> child_viseme(StateId i) const {
    const std::uint8_t v = child_viseme_[i];
    return v < kVisemeClassCount ? std::optional<VisemeClass>(static_cast<VisemeClass>(v)) : std::nullopt;
  }

  // Every state of class v.
  std::span<const StateId> with_viseme(VisemeClass v) const;
  // Every state j of class `to` whose parent is of class `from`: where a unit may start after a
  // unit that ended in class `from` (G = 0 in the paper).
  std::span<const StateId> entries(VisemeClass from, VisemeClass to) const;

  bool has_join_features() const { return features_.entry.rows() > 0; }
  const JoinFeatures& join_features() const { return features_; }
  // The search's lower bound on join costs (empty without features).
  const JoinBound& join_bound() const { return bound_; }

 private:
  std::vector<PhoneState> states_;
  std::vector<std::uint8_t> child_viseme_;  // per state: its child's class, kVisemeClassCount if none
  JoinFeatures features_;
  JoinBound bound_;
  // CSR-style indices: by_viseme_[offsets_[v] .. offsets_[v+1]) and the same for divisemes.
  std::vector<std::uint32_t> viseme_offsets_;
  std::vector<StateId> by_viseme_;
  std::vector<std::uint32_t> diviseme_offsets_;
  std::vector<StateId> by_diviseme_;
};

// Mean squared second derivative of the concatenated PCA trajectory over a join from state
// i (ending a unit) to state j (starting the next): the paper's C, in coefficient units^2/frame^4.
float join_cost(const PhoneGraph& graph, StateId i, StateId j);

}  // namespace fapcast
