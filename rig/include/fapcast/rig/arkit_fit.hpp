#pragma once
// ARKit weights from a voice's synthesis (spec/rigs.md, "The fit"): per frame the 52 weights in
// [0, 1] that best reproduce the synthesised face on the lips, jaw, cheeks and nose, as a bounded
// least-squares problem over the ICT expression shapes on the vertices they move, pre-factored once
// per voice (BoxQp); tongueOut from the tongue track. The residual is reported at the feature points.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "fapcast/rig/arkit_shapes.hpp"
#include "fapcast/rig/box_qp.hpp"

namespace fapcast {

class Voice;
struct FaceModel;

struct ArkitFitOptions {
  // A vertex belongs to the fitted region when some mouth shape moves it more than this (metres).
  double region_motion_m = 1e-4;
  // tongueOut = clamp(thrust_tongue_tip / (this x MW), 0, 1): FAP 45 in MW/1024 units.
  double tongue_out_at_mw = 0.4;
};

// One frame's fit error at the voice's feature points (metres, 3-D distance).
struct ArkitResidual {
  double lips_rms_m = 0;  // inner and outer lip points 2.2-2.9, 8.1-8.8
  double jaw_rms_m = 0;   // chin and jaw 2.1, 2.10-2.14
  double lips_max_m = 0;
  double jaw_max_m = 0;
};

struct ArkitTrack {
  Eigen::MatrixXf weights;              // frames x 52, kArkitShapes order, each in [0, 1]
  ArkitResidual residual;               // over all frames (RMS of every point-frame, max of any)
  std::vector<ArkitResidual> per_frame; // one per frame
  BoxQpStats solver;
};

class ArkitFit {
 public:
  // Pre-factors the fit for `voice` (its PCA mean and components, feature points and face maps)
  // with the shapes of `ict`, the generic face the voice's face was made from. Throws
  // std::invalid_argument when a shape named in kArkitShapes is missing from `ict` or the voice's
  // dimension is not 3 x ict's vertex count.
  ArkitFit(const FaceModel& ict, const Voice& voice, const ArkitFitOptions& options = {});

  // Fits every frame: `pca_frames` frames x k (the voice's coefficients), `tongue` frames x 5
  // (FAP 43..47, synthesis' tongue track) or empty (tongueOut 0). Warm-started frame to frame.
  ArkitTrack fit(const Eigen::MatrixXf& pca_frames, const Eigen::MatrixXf& tongue) const;

  // The fitted columns (indices into kArkitShapes), the region's size, and the metric: the Gram
  // matrix of the fitted columns on the region (so w' H w is the squared displacement, m^2).
  const std::vector<int>& columns() const { return columns_; }
  std::int64_t region_vertices() const { return region_vertices_; }
  const Eigen::MatrixXd& gram() const { return gram_; }
  // The unconstrained optimum for PCA coefficients c (k): u = H^-1 q, what BoxQp starts from.
  Eigen::VectorXd unconstrained(const Eigen::VectorXd& c) const { return u0_ + u_of_c_ * c; }
  // Displacement of the feature point `p` (voice.feature_points() order) for column weights w.
  Eigen::Vector3d point_displacement(std::size_t p, const Eigen::VectorXd& w) const;

 private:
  std::vector<int> columns_;   // fitted kArkitShapes indices (group kMouth)
  std::int64_t region_vertices_ = 0;
  Eigen::MatrixXd gram_;       // n x n
  Eigen::MatrixXd u_of_c_;     // n x k: H^-1 B' PC
  Eigen::VectorXd u0_;         // n: H^-1 B' (mean - neutral)
  std::optional<BoxQp> qp_;
  // feature-point rows: B_fp (3P x n), PC_fp (3P x k), (mean - neutral)_fp (3P)
  Eigen::MatrixXd fp_basis_, fp_components_;
  Eigen::VectorXd fp_offset_;
  std::vector<char> fp_is_lip_, fp_is_jaw_;
  double tongue_out_at_mw_;
};

}  // namespace fapcast
