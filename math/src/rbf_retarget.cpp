#include "fapcast/math/rbf_retarget.hpp"

#include <Eigen/Householder>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace fapcast {
namespace {

// Squared distances between the rows of a (n x d) and the rows of b (m x d): n x m.
Eigen::MatrixXd squared_distances(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  Eigen::MatrixXd d2 = (-2.0 * a * b.transpose()).eval();
  d2.colwise() += a.rowwise().squaredNorm();
  d2.rowwise() += b.rowwise().squaredNorm().transpose();
  return d2.cwiseMax(0.0);  // the expansion can dip below zero by rounding
}

Eigen::MatrixXd gaussian(const Eigen::MatrixXd& d2, double r_squared) {
  return (-d2.array() / r_squared).exp().matrix();
}

// Shrinkage factor s^2 / (s^2 + lambda) of one singular direction; 0 for a null direction.
double shrinkage(double s, double lambda) {
  const double s2 = s * s;
  return s2 == 0.0 ? 0.0 : s2 / (s2 + lambda);
}

}  // namespace

RbfMap::RbfMap(Eigen::MatrixXd centres, double r_squared, Eigen::MatrixXd weights,
               Eigen::VectorXd offset, double lambda)
    : centres_(std::move(centres)), r_squared_(r_squared), weights_(std::move(weights)),
      offset_(std::move(offset)), lambda_(lambda) {
  if (weights_.rows() != centres_.rows() || offset_.size() != weights_.cols() ||
      !(r_squared_ > 0.0)) {
    throw std::invalid_argument("RbfMap: weights must be m x D, offset D, r^2 > 0");
  }
}

Eigen::VectorXd RbfMap::responses(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  if (x.size() != source_dimension()) {
    throw std::invalid_argument("RbfMap::responses: source vector of length " +
                                std::to_string(x.size()) + ", expected " +
                                std::to_string(source_dimension()));
  }
  const Eigen::VectorXd d2 = (centres_.rowwise() - x.transpose()).rowwise().squaredNorm();
  return (-d2.array() / r_squared_).exp().matrix();
}

Eigen::VectorXd RbfMap::operator()(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return offset_ + weights_.transpose() * responses(x);
}

void RbfMap::map_columns(const Eigen::Ref<const Eigen::MatrixXd>& sources,
                         Eigen::Ref<Eigen::MatrixXf> out) const {
  if (sources.rows() != source_dimension() || out.rows() != target_dimension() ||
      out.cols() != sources.cols()) {
    throw std::invalid_argument("RbfMap::map_columns: sources must be d x c and out D x c");
  }
  const Eigen::MatrixXd phi =
      gaussian(squared_distances(centres_, sources.transpose()), r_squared_);  // m x c
  out.noalias() = weights_.transpose().cast<float>() * phi.cast<float>();
  out.colwise() += offset_.cast<float>();
}

RbfRidgeProblem::RbfRidgeProblem(Eigen::MatrixXd centres, const Eigen::MatrixXd& targets,
                                 double r_squared)
    : centres_(std::move(centres)), r_squared_(r_squared) {
  const Eigen::Index m = centres_.rows();
  if (m < 2 || targets.rows() != m || targets.cols() < 1 || centres_.cols() < 1) {
    throw std::invalid_argument("RbfRidgeProblem: need m >= 2 centres (m x d) and m x D targets, got " +
                                std::to_string(m) + " centres and " +
                                std::to_string(targets.rows()) + " target rows");
  }
  if (!(r_squared_ > 0.0) || !std::isfinite(r_squared_)) {
    throw std::invalid_argument("RbfRidgeProblem: r^2 must be finite and > 0");
  }
  if (!centres_.allFinite() || !targets.allFinite()) {
    throw std::invalid_argument("RbfRidgeProblem: centres and targets must be finite");
  }
  kernel_ = gaussian(squared_distances(centres_, centres_), r_squared_);
  kernel_column_mean_ = kernel_.rowwise().mean();  // K is symmetric: row means = column means
  target_mean_ = targets.colwise().mean().transpose();

  // B: an orthonormal basis of the complement of the constant vector (the last m - 1 columns of
  // the Householder reflection that sends e_1 to 1/sqrt(m)). Projecting on it profiles out b.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Eigen::MatrixXd::Ones(m, 1));
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(m, m);
  const Eigen::MatrixXd b = q.rightCols(m - 1);

  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(b.transpose() * kernel_,
                                              Eigen::ComputeFullU | Eigen::ComputeThinV);
  s_ = svd.singularValues();
  v_ = svd.matrixV();
  z_ = svd.matrixU().transpose() * (b.transpose() * targets);  // one pass over all D outputs
  z_energy_ = z_.rowwise().squaredNorm();
}

double RbfRidgeProblem::gcv(double lambda) const {
  double residual = 0.0;
  double trace = 0.0;
  for (Eigen::Index i = 0; i < s_.size(); ++i) {
    const double keep = 1.0 - shrinkage(s_[i], lambda);
    residual += keep * keep * z_energy_[i];
    trace += keep;
  }
  if (trace <= 0.0) return std::numeric_limits<double>::infinity();
  return static_cast<double>(centre_count()) * residual / (trace * trace);
}

double RbfRidgeProblem::effective_parameters(double lambda) const {
  double sum = 1.0;  // the intercept
  for (Eigen::Index i = 0; i < s_.size(); ++i) sum += shrinkage(s_[i], lambda);
  return sum;
}

LambdaChoice RbfRidgeProblem::choose_lambda(int grid_points) const {
  if (grid_points < 3) throw std::invalid_argument("choose_lambda: need >= 3 grid points");
  const double scale = s_.size() > 0 && s_[0] > 0.0 ? s_[0] * s_[0] : 1.0;
  const double lo = std::log(1e-12 * scale);
  const double hi = std::log(1e3 * scale);
  const double step = (hi - lo) / (grid_points - 1);
  int best = 0;
  double best_gcv = std::numeric_limits<double>::infinity();
  for (int i = 0; i < grid_points; ++i) {
    const double g = gcv(std::exp(lo + step * i));
    if (g < best_gcv) {
      best_gcv = g;
      best = i;
    }
  }
  LambdaChoice choice{std::exp(lo + step * best), best_gcv, best == 0 || best == grid_points - 1};
  if (choice.at_range_edge) return choice;
  // Golden-section search in log lambda inside the bracket (best - 1, best + 1).
  const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo + step * (best - 1);
  double b = lo + step * (best + 1);
  double c = b - phi * (b - a);
  double d = a + phi * (b - a);
  double gc = gcv(std::exp(c));
  double gd = gcv(std::exp(d));
  for (int it = 0; it < 60 && b - a > 1e-10; ++it) {
    if (gc < gd) {
      b = d, d = c, gd = gc;
      c = b - phi * (b - a);
      gc = gcv(std::exp(c));
    } else {
      a = c, c = d, gc = gd;
      d = a + phi * (b - a);
      gd = gcv(std::exp(d));
    }
  }
  const double refined = gc < gd ? c : d;
  const double refined_gcv = std::min(gc, gd);
  if (refined_gcv < choice.gcv) choice = {std::exp(refined), refined_gcv, false};
  return choice;
}

RbfMap RbfRidgeProblem::solve(double lambda) const {
  if (!(lambda >= 0.0) || !std::isfinite(lambda)) {
    throw std::invalid_argument("RbfRidgeProblem::solve: lambda must be finite and >= 0");
  }
  Eigen::VectorXd gain(s_.size());
  for (Eigen::Index i = 0; i < s_.size(); ++i) {
    gain[i] = s_[i] == 0.0 ? 0.0 : s_[i] / (s_[i] * s_[i] + lambda);
  }
  Eigen::MatrixXd weights = v_ * (gain.asDiagonal() * z_);  // m x D
  Eigen::VectorXd offset = target_mean_ - weights.transpose() * kernel_column_mean_;
  return RbfMap(centres_, r_squared_, std::move(weights), std::move(offset), lambda);
}

RbfMap fit_rbf_by_gcv(const Eigen::MatrixXd& centres, const Eigen::MatrixXd& targets,
                      double r_squared, LambdaChoice* choice) {
  const RbfRidgeProblem problem(centres, targets, r_squared);
  const LambdaChoice chosen = problem.choose_lambda();
  if (choice != nullptr) *choice = chosen;
  return problem.solve(chosen.lambda);
}

}  // namespace fapcast
