#pragma once
// The phone graph of the paper's section 3.7: one horizontal chain of phone states per recorded
// utterance, indexed so that the unit search never scans the corpus.
#include "fapcast/synth/viseme.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace fapcast::synth {

using StateId = std::uint32_t;

// Frames [first, first + count) of the voice's frame array (60 fps).
struct FrameSpan {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  bool operator==(const FrameSpan&) const = default;
};

// One phone of one recorded utterance.
struct PhoneState {
  std::uint32_t utterance = 0;  // recordings are numbered 0..U-1
  VisemeClass viseme = VisemeClass::kSilence;
  FrameSpan frames;
  bool operator==(const PhoneState&) const = default;
};

// Boundary shape of a state for the junction cost (see junction_cost): `entry` is
// [x0, x1 - 2 x0] of its first two frames, `exit` is [2 x_-1 - x_-2, -x_-1] of its last two,
// where x are the PCA coefficient vectors (k each, so both have 2k entries).
struct JunctionFeatures {
  Eigen::MatrixXf entry;  // states x 2k
  Eigen::MatrixXf exit;   // states x 2k
};

// Makes the junction features of every state from the voice's PCA frames (frames x k). A state
// shorter than two frames borrows frames from its neighbours in the recording.
JunctionFeatures junction_features(std::span<const PhoneState> states,
                                   const Eigen::MatrixXf& pca_frames);

class PhoneGraph {
 public:
  // `states` must list each utterance's phones contiguously and in spoken order; `features`
  // has one row per state (or is empty: then every junction costs only its segment count).
  // Throws std::invalid_argument when a viseme class is out of range, an utterance's states
  // are not contiguous, or the feature rows do not match the states.
  PhoneGraph(std::vector<PhoneState> states, JunctionFeatures features = {});

  std::size_t size() const { return states_.size(); }
  const PhoneState& state(StateId j) const { return states_[j]; }
  std::span<const PhoneState> states() const { return states_; }

  // The previous phone in the same recording, if any.
  bool has_parent(StateId j) const { return j > 0 && states_[j - 1].utterance == states_[j].utterance; }
  bool has_child(StateId i) const {
    return i + 1 < states_.size() && states_[i + 1].utterance == states_[i].utterance;
  }

  // Every state of class v.
  std::span<const StateId> with_viseme(VisemeClass v) const;
  // Every state j of class `to` whose parent is of class `from`: where a unit may start after a
  // unit that ended in class `from` (G = 0 in the paper).
  std::span<const StateId> entries(VisemeClass from, VisemeClass to) const;

  bool has_junction_features() const { return features_.entry.rows() > 0; }
  const JunctionFeatures& junction() const { return features_; }

 private:
  std::vector<PhoneState> states_;
  JunctionFeatures features_;
  // CSR-style indices: by_viseme_[offsets_[v] .. offsets_[v+1]) and the same for divisemes.
  std::vector<std::uint32_t> viseme_offsets_;
  std::vector<StateId> by_viseme_;
  std::vector<std::uint32_t> diviseme_offsets_;
  std::vector<StateId> by_diviseme_;
};

// Mean squared second derivative of the concatenated PCA trajectory over a junction from state
// i (ending a unit) to state j (starting the next): the paper's C, in coefficient units^2/frame^4.
float junction_cost(const PhoneGraph& graph, StateId i, StateId j);

}  // namespace fapcast::synth
