#pragma once
// Streaming first and second moments of a sequence of vectors (Welford's update, double), so a
// corpus of frames is summarised in one pass without holding it: the RBF width r^2 needs the mean
// squared distance from the mean (paper section 3.5), the exact PCA route needs the covariance of
// the basis responses (section 3.6).
#include <Eigen/Core>
#include <cstdint>

namespace fapcast {

// Mean and total variance (mean squared distance from the mean) of vectors of one dimension.
// Memory O(dimension); each add() is O(dimension).
class RunningSpread {
 public:
  // `dimension` >= 1: the length of every vector passed to add().
  explicit RunningSpread(Eigen::Index dimension);

  // Adds one vector (length must equal dimension(); throws std::invalid_argument otherwise).
  void add(const Eigen::Ref<const Eigen::VectorXd>& x);

  Eigen::Index dimension() const { return mean_.size(); }
  std::int64_t count() const { return count_; }
  const Eigen::VectorXd& mean() const { return mean_; }
  // mean over the added vectors of ||x - mean||^2 (population, divides by count); 0 when empty.
  double mean_squared_distance() const;

 private:
  std::int64_t count_ = 0;
  Eigen::VectorXd mean_;
  Eigen::VectorXd sum_sq_dev_;  // per coordinate: sum of squared deviations (Welford M2)
};

// Mean and full covariance of vectors of a small dimension (the m basis responses of an RBF
// network). Memory O(dimension^2); each add() is O(dimension^2).
class RunningCovariance {
 public:
  explicit RunningCovariance(Eigen::Index dimension);

  // Adds one vector (length must equal dimension(); throws std::invalid_argument otherwise).
  void add(const Eigen::Ref<const Eigen::VectorXd>& x);

  Eigen::Index dimension() const { return mean_.size(); }
  std::int64_t count() const { return count_; }
  const Eigen::VectorXd& mean() const { return mean_; }
  // Population covariance (divides by count), symmetric; zero matrix when empty.
  Eigen::MatrixXd covariance() const;

 private:
  std::int64_t count_ = 0;
  Eigen::VectorXd mean_;
  Eigen::MatrixXd sum_outer_dev_;  // Welford co-moment: sum (x - mean_old)(x - mean_new)^T
};

}  // namespace fapcast
