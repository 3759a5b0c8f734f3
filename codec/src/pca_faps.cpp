#include "fapcast/codec/pca_faps.hpp"

#include "fapcast/codec/fap_axis.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fapcast::codec {
namespace {

constexpr FeaturePoint kChin{2, 1};

// One driven FAP: which basis point, along which axis, in how long a unit.
struct Drive {
  int fap;
  std::size_t point;
  Eigen::Vector3d axis;
  bool jaw_relative;
};

// `units` of a FAP rounded half away from zero (std::round), saturated to int32 (NaN: the minimum).
std::int32_t rounded_fap_value(double units) {
  const double v = std::round(units);
  constexpr double lo = std::numeric_limits<std::int32_t>::min(), hi = std::numeric_limits<std::int32_t>::max();
  if (!(v >= lo)) return std::numeric_limits<std::int32_t>::min();  // also NaN
  return v > hi ? std::numeric_limits<std::int32_t>::max() : static_cast<std::int32_t>(v);
}

}  // namespace

bool is_jaw_borne(FeaturePoint fp) {
  if (fp.group == 6) return fp.index >= 1 && fp.index <= 4;
  if (fp.group == 2) return fp.index == 3 || fp.index == 8 || fp.index == 9 || fp.index == 10;
  if (fp.group == 8) return fp.index == 2 || fp.index == 7 || fp.index == 8;
  return false;
}

FapMask drivable_faps(const FeaturePointBasis& basis) {
  FapMask mask;
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap) {
    const FapInfo& info = fap_info(fap);
    if (info.feature_point && basis.index_of(*info.feature_point) && fap_axis(fap)) mask.set(fap);
  }
  return mask;
}

std::int32_t to_fap_value(int fap, double amount, const FapuValues& fapu) {
  return rounded_fap_value(amount / fapu.of(fap_info(fap).unit));
}

std::vector<FapFrame> pca_to_faps(const Eigen::MatrixXf& coefficients, const FeaturePointBasis& basis,
                                  const PcaFapOptions& options) {
  if (coefficients.cols() != basis.component_count())
    throw std::invalid_argument("PCA to FAP: frames have " + std::to_string(coefficients.cols()) +
                                " coefficients, the basis " + std::to_string(basis.component_count()));
  const FapuValues fapu = measure_fapu(basis.neutral);
  const auto chin = basis.index_of(kChin);
  std::vector<Drive> drives;
  const FapMask mask = drivable_faps(basis);
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap)
    if (mask.test(fap)) {
      const FeaturePoint fp = *fap_info(fap).feature_point;
      drives.push_back({fap, *basis.index_of(fp), *fap_axis(fap),
                        options.jaw_relative && chin.has_value() && is_jaw_borne(fp)});
    }
  // Neutral positions in basis order, so a displacement is one subtraction.
  const auto p = static_cast<Eigen::Index>(basis.points.size());
  Eigen::RowVectorXd rest(3 * p);
  for (Eigen::Index i = 0; i < p; ++i) rest.segment<3>(3 * i) = basis.neutral.at(basis.points[static_cast<std::size_t>(i)]).transpose();
  const Eigen::RowVectorXd offset = basis.mean - rest;

  // A driven FAP's amount is linear in the coefficients: the displacement of its point (minus the
  // chin's, when jaw-relative) along its axis. One weight column and one constant per FAP, so a
  // frame is one k x FAPs product.
  const auto k = basis.component_count();
  const auto count = static_cast<Eigen::Index>(drives.size());
  Eigen::MatrixXd weight(k, count);
  Eigen::RowVectorXd constant(count), unit(count);
  for (Eigen::Index m = 0; m < count; ++m) {
    const Drive& drive = drives[static_cast<std::size_t>(m)];
    const Eigen::Index at = 3 * static_cast<Eigen::Index>(drive.point);
    Eigen::MatrixXd move = basis.components.middleCols<3>(at);
    Eigen::RowVector3d still = offset.segment<3>(at);
    if (drive.jaw_relative) {
      const Eigen::Index jaw = 3 * static_cast<Eigen::Index>(*chin);
      move -= basis.components.middleCols<3>(jaw);
      still -= offset.segment<3>(jaw);
    }
    weight.col(m) = move * drive.axis;
    constant(m) = still.dot(drive.axis);
    unit(m) = fapu.of(fap_info(drive.fap).unit);
  }
  const Eigen::MatrixXd amount = (coefficients.cast<double>() * weight).rowwise() + constant;  // frames x FAPs

  std::vector<FapFrame> frames(static_cast<std::size_t>(coefficients.rows()));
  for (Eigen::Index n = 0; n < coefficients.rows(); ++n) {
    FapFrame& f = frames[static_cast<std::size_t>(n)];
    for (Eigen::Index m = 0; m < count; ++m)
      f.set(drives[static_cast<std::size_t>(m)].fap, rounded_fap_value(amount(n, m) / unit(m)));
  }
  return frames;
}

}  // namespace fapcast::codec
