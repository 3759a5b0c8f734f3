#pragma once
// The lip measures of Ma et al. 2006, section 4.1, used to score retargeting and synthesis:
// lip height (upper to lower mid-lip, FP 8.1 to 8.2), lip width (corner to corner, FP 8.3 to 8.4)
// and lip protrusion (upper mid-lip FP 8.1 to a reference point near the jaw root). The
// reference point is the midpoint of the rigid temple markers H.temple_l / H.temple_r
// (spec/markers.tsv): it sits above the jaw joints, moves with the skull only, and exists both in
// a capture (as markers) and on the ICT mesh (as vertices), so both sides measure the same thing.
#include "fapcast/corpus/marker_frames.hpp"
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace fapcast {

// The five points the measures need, in any one length unit.
struct LipPoints {
  Eigen::Vector3d upper_mid;     // FP 8.1
  Eigen::Vector3d lower_mid;     // FP 8.2
  Eigen::Vector3d left_corner;   // FP 8.3
  Eigen::Vector3d right_corner;  // FP 8.4
  Eigen::Vector3d reference;     // midpoint of H.temple_l and H.temple_r
};

// Marker labels behind LipPoints, in member order; the reference is the mean of the last two.
inline constexpr std::array<std::string_view, 6> kLipMarkerLabels = {
    "8.1", "8.2", "8.3", "8.4", "H.temple_l", "H.temple_r"};

// Lengths in the unit of the points.
struct LipMeasures {
  double height = 0;
  double width = 0;
  double protrusion = 0;
};

LipMeasures measure_lips(const LipPoints& points);

// Per-frame curves of the three measures (NaN where a frame could not be measured).
struct LipCurves {
  std::vector<double> height;
  std::vector<double> width;
  std::vector<double> protrusion;

  std::size_t size() const { return height.size(); }
  void push_back(const LipMeasures& m);
  // Appends another utterance's curves (a corpus is scored as one long curve).
  void append(const LipCurves& other);
};

// The curves of a take; a frame with any of the six markers missing (NaN) gives NaN measures.
// Throws std::invalid_argument naming a label the take does not have.
LipCurves lip_curves(const MarkerFrames<Centimetres>& take);

// The curves of mesh frames: `frames` is F x 3N (xyz interleaved per vertex, any unit) and
// `vertices` the six mesh vertices of kLipMarkerLabels (e.g. from marker_map's table).
LipCurves lip_curves(const Eigen::Ref<const Eigen::MatrixXf>& frames,
                     std::span<const std::int32_t, 6> vertices);

// How well a candidate curve follows a reference curve of the same length.
struct CurveAgreement {
  double mean_error_percent = 0;  // mean |a/max(a) - b/max(b)| x 100, the paper's figure
  double correlation = 0;         // Pearson correlation of a and b (0 when either is constant)
  std::size_t frames = 0;         // frames where both are defined
  // mean |a - b| in the curves' own unit: meaningful only when both curves are on one face (eval
  // synth), where it does not hang on each curve's single highest frame as the normalised error does
  double mean_abs_difference = 0;
};

struct LipAgreement {
  CurveAgreement height;
  CurveAgreement width;
  CurveAgreement protrusion;
};

// Each curve is normalised by its own maximum, so a small and a large face that move alike agree
// (the source actor and the target face differ in size). Frames where either side is NaN are
// skipped. Throws std::invalid_argument when the lengths differ.
CurveAgreement compare_curves(std::span<const double> reference, std::span<const double> candidate);
LipAgreement compare_lip_curves(const LipCurves& reference, const LipCurves& candidate);

}  // namespace fapcast
