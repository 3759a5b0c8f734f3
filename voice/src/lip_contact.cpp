#include "fapcast/voice/lip_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fapcast {

double LipContact::source_gap_m(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return (x.segment<3>(source_upper) - x.segment<3>(source_lower)).norm();
}

double LipContact::amount(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& phi) const {
  const double above = std::max(0.0, source_gap_m(x) - source_contact_m);
  if (!(above < reach_m) || !(shape_gap_m < 0)) return 0.0;
  const double excess = gap_offset_m + gap_weights.dot(phi) - (target_contact_m + above);
  if (!(excess > 0)) return 0.0;
  // 1 up to half the reach, then a half cosine down to 0 at the reach.
  const double t = std::clamp(2.0 * above / reach_m - 1.0, 0.0, 1.0);
  const double fade = 0.5 * (1.0 + std::cos(std::numbers::pi * t));
  return std::min(kMaxAmount, fade * excess / -shape_gap_m);
}

Retargeting::Retargeting(const RbfMap& map, std::optional<LipContact> contact)
    : map_(&map), contact_(std::move(contact)) {
  if (!contact_) {
    weights_ = map.weights();
    return;
  }
  const LipContact& c = *contact_;
  const Eigen::Index d = map.source_dimension();
  if (c.shape.size() != map.target_dimension() || c.gap_weights.size() != map.centre_count() || c.source_upper < 0 ||
      c.source_upper + 3 > d || c.source_lower < 0 || c.source_lower + 3 > d)
    throw std::invalid_argument("Retargeting: the lip-contact term does not fit the map's dimensions");
  weights_.resize(map.centre_count() + 1, map.target_dimension());
  weights_.topRows(map.centre_count()) = map.weights();
  weights_.bottomRows(1) = c.shape.transpose();
}

Eigen::VectorXd Retargeting::responses(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  if (!contact_) return map_->responses(x);
  Eigen::VectorXd out(response_count());
  out.head(map_->centre_count()) = map_->responses(x);
  out(map_->centre_count()) = contact_->amount(x, out.head(map_->centre_count()));
  return out;
}

Eigen::VectorXd Retargeting::operator()(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return offset() + weights_.transpose() * responses(x);
}

void Retargeting::map_columns(const Eigen::Ref<const Eigen::MatrixXd>& sources, Eigen::Ref<Eigen::MatrixXf> out) const {
  if (!contact_) {
    map_->map_columns(sources, out);
    return;
  }
  // The amount needs each column's responses: one pass makes them all, then one product.
  if (sources.rows() != source_dimension() || out.rows() != target_dimension() || out.cols() != sources.cols())
    throw std::invalid_argument("Retargeting::map_columns: sources must be d x c and out D x c");
  Eigen::MatrixXf responses_of(response_count(), sources.cols());
  for (Eigen::Index f = 0; f < sources.cols(); ++f) responses_of.col(f) = responses(sources.col(f)).cast<float>();
  out.noalias() = weights_.transpose().cast<float>() * responses_of;
  out.colwise() += offset().cast<float>();
}

}  // namespace fapcast
