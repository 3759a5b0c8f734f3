#pragma once
// PCA frames -> FAP frames: each low-level FAP whose feature point the basis carries is the
// point's displacement from the NEUTRAL face along the FAP's axis (fap_axis.hpp), in the FAPU
// measured on that neutral face. The jaw comes from the chin (2.1: FAP 3 open_jaw down,
// 14 thrust_jaw forward, 15 shift_jaw to the face's right). spec/synthesis.md has the rules.
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/codec/feature_point_basis.hpp"

#include <Eigen/Core>

#include <vector>

namespace fapcast {

// The points that ride on the jaw: lower lip (2.3, 2.8, 2.9, 8.2, 8.7, 8.8), chin boss (2.10)
// and tongue (6.1-6.4). A player opens the jaw and then adds their own FAPs, so their
// displacement is measured relative to the chin's.
bool is_jaw_borne(FeaturePoint fp);

struct PcaFapOptions {
  // Measure jaw-borne points relative to the chin's displacement (when the basis has 2.1).
  bool jaw_relative = true;
};

// The FAPs pca_to_faps drives on `basis`: 3..68 whose feature point is in the basis and whose
// direction is a translation (not pupils, eyeballs, head, tongue roll).
FapMask drivable_faps(const FeaturePointBasis& basis);

// A FAP value for `amount` (a length along the FAP's axis in the face's unit, or an angle in
// radians for AU FAPs): amount / fapu.of(unit), rounded half away from zero, saturated to int32.
std::int32_t to_fap_value(int fap, double amount, const FapuValues& fapu);

// One FapFrame per row of `coefficients` (frames x k, k = basis.component_count()), masked
// with drivable_faps. FAPU from measure_fapu(basis.neutral). Throws std::invalid_argument when
// k differs or the neutral face lacks a FAPU point.
std::vector<FapFrame> pca_to_faps(const Eigen::MatrixXf& coefficients, const FeaturePointBasis& basis,
                                  const PcaFapOptions& options = {});

}  // namespace fapcast
