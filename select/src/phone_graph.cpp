#include "fapcast/select/phone_graph.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fapcast {
namespace {

constexpr std::size_t index(VisemeClass v) { return static_cast<std::size_t>(v); }

constexpr std::size_t diviseme_key(VisemeClass from, VisemeClass to) {
  return index(from) * kVisemeClassCount + index(to);
}

// Groups `ids` by `key(id)` (< buckets) into CSR arrays, keeping ids ascending in each bucket.
template <class Key>
void bucket(std::size_t n, std::size_t buckets, Key key, std::vector<std::uint32_t>& offsets,
            std::vector<StateId>& ids) {
  offsets.assign(buckets + 1, 0);
  for (StateId j = 0; j < n; ++j)
    if (auto k = key(j); k < buckets) ++offsets[k + 1];
  for (std::size_t b = 0; b < buckets; ++b) offsets[b + 1] += offsets[b];
  ids.assign(offsets.back(), 0);
  std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
  for (StateId j = 0; j < n; ++j)
    if (auto k = key(j); k < buckets) ids[fill[k]++] = j;
}

}  // namespace

PhoneGraph::PhoneGraph(std::vector<PhoneState> states, JoinFeatures features)
    : states_(std::move(states)), features_(std::move(features)) {
  for (std::size_t j = 0; j < states_.size(); ++j) {
    if (index(states_[j].viseme) >= kVisemeClassCount)
      throw std::invalid_argument("phone graph: state " + std::to_string(j) + " has viseme class " +
                                  std::to_string(index(states_[j].viseme)) + ", at most " +
                                  std::to_string(kVisemeClassCount - 1) + " allowed");
    if (j > 0 && states_[j].utterance < states_[j - 1].utterance)
      throw std::invalid_argument("phone graph: utterance " + std::to_string(states_[j].utterance) +
                                  " is not contiguous (state " + std::to_string(j) + ")");
  }
  const auto rows = static_cast<std::size_t>(features_.entry.rows());
  if (rows != 0 && (rows != states_.size() || features_.exit.rows() != features_.entry.rows() ||
                    features_.exit.cols() != features_.entry.cols() ||
                    features_.entry.cols() % kJoinLanes != 0))
    throw std::invalid_argument("phone graph: join features have " + std::to_string(rows) + " rows of " +
                                std::to_string(features_.entry.cols()) + " columns for " +
                                std::to_string(states_.size()) + " states (one row per state, columns a multiple of " +
                                std::to_string(kJoinLanes) + ")");
  static_assert(kVisemeClassCount < 256, "a class fits one byte");
  child_viseme_.assign(states_.size(), static_cast<std::uint8_t>(kVisemeClassCount));
  for (StateId i = 0; i < states_.size(); ++i)
    if (has_child(i)) child_viseme_[i] = static_cast<std::uint8_t>(index(states_[i + 1].viseme));
  const std::size_t none = SIZE_MAX;
  bucket(states_.size(), kVisemeClassCount, [&](StateId j) -> std::size_t { return index(states_[j].viseme); },
         viseme_offsets_, by_viseme_);
  bucket(states_.size(), kVisemeClassCount * kVisemeClassCount,
         [&](StateId j) -> std::size_t {
           return has_parent(j) ? diviseme_key(states_[j - 1].viseme, states_[j].viseme) : none;
         },
         diviseme_offsets_, by_diviseme_);
  if (has_join_features()) bound_ = JoinBound(*this);
}

std::span<const StateId> PhoneGraph::with_viseme(VisemeClass v) const {
  const auto i = index(v);
  if (i >= kVisemeClassCount) return {};
  return std::span(by_viseme_).subspan(viseme_offsets_[i], viseme_offsets_[i + 1] - viseme_offsets_[i]);
}

std::span<const StateId> PhoneGraph::entries(VisemeClass from, VisemeClass to) const {
  if (index(from) >= kVisemeClassCount || index(to) >= kVisemeClassCount) return {};
  const auto k = diviseme_key(from, to);
  return std::span(by_diviseme_).subspan(diviseme_offsets_[k], diviseme_offsets_[k + 1] - diviseme_offsets_[k]);
}

JoinFeatures join_features(std::span<const PhoneState> states, const PcaFrames& pca_frames) {
  const Eigen::Index k = pca_frames.cols();
  const Eigen::Index width = (2 * k + kJoinLanes - 1) / kJoinLanes * kJoinLanes;
  const auto rows = static_cast<Eigen::Index>(states.size());
  JoinFeatures f{JoinRows::Zero(rows, width), JoinRows::Zero(rows, width)};
  // Frames of one recording are contiguous; a short state reads past its own span into its
  // neighbours, but never past its recording.
  for (std::size_t u_begin = 0; u_begin < states.size();) {
    std::size_t u_end = u_begin;  // last state of this recording
    while (u_end + 1 < states.size() && states[u_end + 1].utterance == states[u_begin].utterance) ++u_end;
    const std::int64_t lo = states[u_begin].frames.first;
    const std::int64_t hi = std::int64_t{states[u_end].frames.first} + states[u_end].frames.count - 1;
    if (hi >= pca_frames.rows())
      throw std::invalid_argument("phone graph: recording " + std::to_string(states[u_begin].utterance) +
                                  " reaches past the last PCA frame");
    auto x = [&](std::int64_t n) { return pca_frames.row(static_cast<Eigen::Index>(std::clamp(n, lo, hi))); };
    for (std::size_t j = u_begin; j <= u_end; ++j) {
      const auto& s = states[j];
      if (s.frames.count == 0)
        throw std::invalid_argument("phone graph: state " + std::to_string(j) + " spans no frames");
      const std::int64_t first = s.frames.first, last = first + s.frames.count - 1;
      const auto r = static_cast<Eigen::Index>(j);
      f.entry.row(r).head(2 * k) << x(first), x(first + 1) - 2 * x(first);
      f.exit.row(r).head(2 * k) << 2 * x(last) - x(last - 1), -x(last);
    }
    u_begin = u_end + 1;
  }
  return f;
}

float join_cost(const PhoneGraph& graph, StateId i, StateId j) {
  if (!graph.has_join_features()) return 0.0f;
  const auto& f = graph.join_features();
  // Two second differences straddle the join; C is their mean squared norm.
  return join_cost(f.entry.row(j).data(), f.exit.row(i).data(), f.entry.cols());
}

}  // namespace fapcast
