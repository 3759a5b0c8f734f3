#pragma once
// Concatenating selected units as one trajectory (paper sections 3.7-3.8): each unit is time-warped
// onto the target phone durations, neighbouring units are cross-faded at their joins, and the
// result is smoothed so that join jumps go away while lip closures keep their depth.
#include "fapcast/select/phone_graph.hpp"
#include "fapcast/select/unit_search.hpp"
#include "fapcast/voice/voice_frame_grid.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <span>

namespace fapcast {

struct ConcatenationOptions {
  int blend_half_width = 3;        // frames each side of a join that are cross-faded (>= 0)
  double smoothing = 2.0;          // lambda of the smoother; 0 = none (see smooth_trajectory)
  double hold_weight = 50.0;       // data weight inside held phones (1 elsewhere)
  // Where a unit takes over: in the middle of the phone before its first (true), showing its own
  // recording's previous state there - the search's join rule (G = 0) guarantees that state has
  // the class of the phone it stands in for - or at the boundary of its first phone (false).
  // Mid-phone, the hand-over falls where the lips move least (spec/search.md, "Concatenation"); hard
  // joins stay at the boundary.
  bool join_mid_phone = true;
};

// Concatenates the units of `result` (one state per target phone) over `targets`, sampling the
// voice's PCA frames (frames x k). Returns end_frame(last) - first_frame(first) rows of k.
// Throws std::invalid_argument if targets and result disagree or a target has no frames.
Eigen::MatrixXf concatenate_units(const PhoneGraph& graph, const PcaFrames& pca_frames,
                             const SearchResult& result, std::span<const TargetPhone> targets,
                             const ConcatenationOptions& options = {});

// A discrete cubic smoothing spline (Whittaker-Henderson, second differences): the y minimising
// sum_n w_n |y_n - x_n|^2 + lambda sum_n |y_{n+1} - 2 y_n + y_{n-1}|^2, column by column, by one
// banded factorisation shared by all columns. Large weights pin frames (closures) in place.
// Weights must be positive; lambda <= 0 returns x unchanged.
Eigen::MatrixXf smooth_trajectory(const Eigen::MatrixXf& x, std::span<const double> weights,
                                  double lambda);

}  // namespace fapcast
