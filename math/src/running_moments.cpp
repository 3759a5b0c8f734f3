#include "fapcast/math/running_moments.hpp"

#include <stdexcept>
#include <string>

namespace fapcast {
namespace {
void check_length(Eigen::Index got, Eigen::Index want, const char* who) {
  if (got != want) {
    throw std::invalid_argument(std::string(who) + ": vector of length " + std::to_string(got) +
                                ", expected " + std::to_string(want));
  }
}
void check_dimension(Eigen::Index dimension, const char* who) {
  if (dimension < 1) throw std::invalid_argument(std::string(who) + ": dimension must be >= 1");
}
}  // namespace

RunningSpread::RunningSpread(Eigen::Index dimension) {
  check_dimension(dimension, "RunningSpread");
  mean_ = Eigen::VectorXd::Zero(dimension);
  sum_sq_dev_ = Eigen::VectorXd::Zero(dimension);
}

void RunningSpread::add(const Eigen::Ref<const Eigen::VectorXd>& x) {
  check_length(x.size(), dimension(), "RunningSpread::add");
  ++count_;
  const Eigen::VectorXd delta = x - mean_;
  mean_ += delta / static_cast<double>(count_);
  sum_sq_dev_.array() += delta.array() * (x - mean_).array();
}

double RunningSpread::mean_squared_distance() const {
  return count_ == 0 ? 0.0 : sum_sq_dev_.sum() / static_cast<double>(count_);
}

RunningCovariance::RunningCovariance(Eigen::Index dimension) {
  check_dimension(dimension, "RunningCovariance");
  mean_ = Eigen::VectorXd::Zero(dimension);
  sum_outer_dev_ = Eigen::MatrixXd::Zero(dimension, dimension);
}

void RunningCovariance::add(const Eigen::Ref<const Eigen::VectorXd>& x) {
  check_length(x.size(), dimension(), "RunningCovariance::add");
  ++count_;
  const Eigen::VectorXd delta = x - mean_;
  mean_ += delta / static_cast<double>(count_);
  sum_outer_dev_.noalias() += delta * (x - mean_).transpose();
}

Eigen::MatrixXd RunningCovariance::covariance() const {
  if (count_ == 0) return Eigen::MatrixXd::Zero(dimension(), dimension());
  const Eigen::MatrixXd c = sum_outer_dev_ / static_cast<double>(count_);
  return 0.5 * (c + c.transpose());  // the Welford co-moment is symmetric only up to rounding
}

}  // namespace fapcast
