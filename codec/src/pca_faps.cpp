#include "fapcast/codec/pca_faps.hpp"

#include <algorithm>

#include "fapcast/codec/fap_axis.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <cmath>
#include <span>
#include <limits>
#include <stdexcept>
#include <string>

namespace fapcast {
namespace {

constexpr FeaturePoint kChin{2, 1};

// One driven FAP: which basis point, along which axis, in how long a unit.
struct Drive {
  int fap;
  std::size_t point;
  Eigen::Vector3d axis;
  bool jaw_relative;
};

constexpr double kInt32Low = std::numeric_limits<std::int32_t>::min();
constexpr double kInt32High = std::numeric_limits<std::int32_t>::max();

// std::round(units) for kInt32Low <= units <= kInt32High, without a libm call (x86-64 has no
// rounding instruction below SSE4.1): truncation is exact there, and so is the fraction units - t,
// so halves go away from zero exactly as std::round's do. The result stays inside int32.
std::int32_t rounded_inside_int32(double units) {
  const auto t = static_cast<std::int32_t>(units);
  const double fraction = units - static_cast<double>(t);
  return t + static_cast<std::int32_t>(fraction >= 0.5) - static_cast<std::int32_t>(fraction <= -0.5);
}

// `units` of a FAP rounded half away from zero (std::round), saturated to int32 (NaN: the minimum).
std::int32_t rounded_fap_value(double units) {
  if (units >= kInt32Low && units <= kInt32High) return rounded_inside_int32(units);
  if (!(units >= kInt32Low)) return std::numeric_limits<std::int32_t>::min();  // also NaN
  return std::numeric_limits<std::int32_t>::max();
}

// One frame's FAP values, rounded_fap_value((amount[m] + constant[m]) / unit[m]) for each m, two at
// a time where SSE2 (every x86-64) has the instructions: the same sum and quotient, then
// truncation, the fraction, and the half-away-from-zero step, as above.
void frame_fap_values(const double* amount, const double* constant, const double* unit,
                      std::span<std::int32_t> out) {
  std::size_t m = 0;
#if defined(__SSE2__)
  const __m128d lo = _mm_set1_pd(kInt32Low), hi = _mm_set1_pd(kInt32High);
  const __m128d half = _mm_set1_pd(0.5), minus_half = _mm_set1_pd(-0.5);
  for (; m + 2 <= out.size(); m += 2) {
    const __m128d x = _mm_div_pd(_mm_add_pd(_mm_loadu_pd(amount + m), _mm_loadu_pd(constant + m)), _mm_loadu_pd(unit + m));
    if (_mm_movemask_pd(_mm_and_pd(_mm_cmpge_pd(x, lo), _mm_cmple_pd(x, hi))) != 3) {  // also NaN
      out[m] = rounded_fap_value(_mm_cvtsd_f64(x));
      out[m + 1] = rounded_fap_value(_mm_cvtsd_f64(_mm_unpackhi_pd(x, x)));
      continue;
    }
    const __m128i t = _mm_cvttpd_epi32(x);
    const __m128d fraction = _mm_sub_pd(x, _mm_cvtepi32_pd(t));
    // Comparisons give all-ones (-1) lanes: t + up - down = t + (down_mask - up_mask), whose
    // 64-bit lanes' low halves are moved next to each other.
    const __m128i up = _mm_castpd_si128(_mm_cmpge_pd(fraction, half));
    const __m128i down = _mm_castpd_si128(_mm_cmple_pd(fraction, minus_half));
    const __m128i step = _mm_shuffle_epi32(_mm_sub_epi64(down, up), _MM_SHUFFLE(2, 0, 2, 0));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out.data() + m), _mm_add_epi32(t, step));
  }
#endif
  for (; m < out.size(); ++m) out[m] = rounded_fap_value((amount[m] + constant[m]) / unit[m]);
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
  Eigen::MatrixXd move(k, 3);  // one buffer for every FAP's point motion
  for (Eigen::Index m = 0; m < count; ++m) {
    const Drive& drive = drives[static_cast<std::size_t>(m)];
    const Eigen::Index at = 3 * static_cast<Eigen::Index>(drive.point);
    move = basis.components.middleCols<3>(at);
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
  // FAPs x frames, a block of frames at a time (the scratch stays the same for any length): a
  // frame's amounts are one column, written to its FapFrame in one go.
  constexpr Eigen::Index kBlockFrames = 4096;
  Eigen::MatrixXd product;

  std::vector<std::size_t> slot(drives.size());  // where FAP m's value goes in FapFrame::values
  for (std::size_t m = 0; m < drives.size(); ++m) {
    slot[m] = fap_slot(drives[m].fap);
  }
  std::vector<FapFrame> frames;  // built a frame at a time, so each is written while in cache
  frames.reserve(static_cast<std::size_t>(coefficients.rows()));
  std::vector<std::int32_t> values(drives.size());
  for (Eigen::Index start = 0; start < coefficients.rows(); start += kBlockFrames) {
    const Eigen::Index block = std::min(kBlockFrames, coefficients.rows() - start);
    product.noalias() = weight.transpose() * coefficients.middleRows(start, block).cast<double>().transpose();
    for (Eigen::Index n = 0; n < block; ++n) {
      frame_fap_values(product.col(n).data(), constant.data(), unit.data(), values);
      FapFrame& f = frames.emplace_back();
      f.mask = mask;
      for (std::size_t m = 0; m < slot.size(); ++m) f.values[slot[m]] = values[m];
    }
  }
  return frames;
}

}  // namespace fapcast
