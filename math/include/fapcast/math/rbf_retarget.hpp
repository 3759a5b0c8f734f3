#pragma once
// Gaussian RBF retargeting (Ma et al. 2006, section 3.5): a map from a source marker vector
// x in R^d (d = 3p, p markers) to a target mesh vector y in R^D (D = 3N, N vertices), learned from
// m training pairs (x_k, y_k) - the 21 source/target prototypes, or any m >= 2 centres:
//
//   y(x) = b + sum_j w_j phi_j(x),   phi_j(x) = exp(-||x - c_j||^2 / r^2),   c_j = x_j,
//
// with r^2 the mean squared distance of ALL corpus frames from their mean (RunningSpread), and
// the weights W (m x D) from ridge regression whose lambda is chosen by generalised
// cross-validation. The constant b is an unpenalised intercept (why: Gaussians decay to 0 away
// from every centre, so without b a marker vector outside the prototypes' reach would map to the
// zero vector - a face collapsed onto the origin - and ridge shrinkage would pull every vertex
// towards the origin; with b both fall back to the mean prototype face. A full affine term would
// add d = 3p >> m unknowns and is not identifiable from 21 pairs.)
//
// One decomposition serves every lambda and every output: the intercept is profiled out by
// projecting onto the (m-1)-dimensional complement B of the constant vector, the m x m kernel is
// decomposed once, B^T K = U S V^T, and then for each lambda
//   H(lambda) = 11^T/m + B U diag(s_i^2 / (s_i^2 + lambda)) U^T B^T      (the hat matrix)
//   GCV(lambda) = m ||(I - H) Y||_F^2 / trace(I - H)^2
// costs O(m) given the per-direction energies ||U^T B^T Y||, so a dense lambda grid is free.
#include <Eigen/Core>
#include <vector>

namespace fapcast {

// A fitted map: centres, width, weights and intercept. Evaluates one frame or a chunk of frames.
class RbfMap {
 public:
  RbfMap(Eigen::MatrixXd centres, double r_squared, Eigen::MatrixXd weights,
         Eigen::VectorXd offset, double lambda);

  Eigen::Index centre_count() const { return centres_.rows(); }    // m
  Eigen::Index source_dimension() const { return centres_.cols(); } // d = 3p
  Eigen::Index target_dimension() const { return weights_.cols(); } // D = 3N
  const Eigen::MatrixXd& centres() const { return centres_; }      // m x d, one centre per row
  double r_squared() const { return r_squared_; }
  const Eigen::MatrixXd& weights() const { return weights_; }      // m x D
  const Eigen::VectorXd& offset() const { return offset_; }        // D, the intercept b
  double lambda() const { return lambda_; }

  // The m basis responses phi_j(x) of one source vector x (length d).
  Eigen::VectorXd responses(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // The target vector y(x) = b + W^T phi(x) (length D).
  Eigen::VectorXd operator()(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // Maps a chunk of source frames (d x c, one frame per column) into `out` (D x c, float32):
  // the streaming path of the voice build, one GEMM per chunk.
  void map_columns(const Eigen::Ref<const Eigen::MatrixXd>& sources,
                   Eigen::Ref<Eigen::MatrixXf> out) const;

 private:
  Eigen::MatrixXd centres_;
  double r_squared_;
  Eigen::MatrixXd weights_;
  Eigen::VectorXd offset_;
  double lambda_;
};

// Which lambda GCV chose, and whether the minimum sat on the edge of the searched range (then the
// data prefer "interpolate exactly" or "constant face" and the caller may want to know).
struct LambdaChoice {
  double lambda = 0;
  double gcv = 0;
  bool at_range_edge = false;
};

// The ridge problem for fixed centres, width and targets, decomposed once.
class RbfRidgeProblem {
 public:
  // `centres` m x d (rows are source prototype vectors; m >= 2), `targets` m x D (rows are the
  // matching target vectors), `r_squared` > 0. Throws std::invalid_argument on bad shapes/width.
  RbfRidgeProblem(Eigen::MatrixXd centres, const Eigen::MatrixXd& targets, double r_squared);

  Eigen::Index centre_count() const { return centres_.rows(); }
  // The m x m Gaussian kernel K_ij = phi_j(c_i).
  const Eigen::MatrixXd& kernel() const { return kernel_; }
  // Singular values of B^T K (m - 1 of them, descending): the scale lambda is measured against.
  const Eigen::VectorXd& singular_values() const { return s_; }

  // GCV(lambda) = m ||(I - H) Y||^2 / trace(I - H)^2, for lambda >= 0; +inf when trace(I-H) = 0.
  double gcv(double lambda) const;
  // trace(H(lambda)): the effective number of parameters (1 for the intercept + shrunk weights).
  double effective_parameters(double lambda) const;
  // Minimises GCV over lambda in [1e-12, 1e3] * s_max^2: a log grid of `grid_points`, then a
  // golden-section refinement in log lambda between the best point's neighbours.
  LambdaChoice choose_lambda(int grid_points = 241) const;
  // The map for one lambda >= 0 (lambda = 0 interpolates when the centres are distinct).
  RbfMap solve(double lambda) const;

 private:
  Eigen::MatrixXd centres_;
  double r_squared_;
  Eigen::MatrixXd kernel_;
  Eigen::VectorXd kernel_column_mean_;  // K 1 / m
  Eigen::VectorXd target_mean_;         // Y^T 1 / m
  Eigen::VectorXd s_;                   // singular values of B^T K, m - 1
  Eigen::MatrixXd v_;                   // right singular vectors, m x (m - 1)
  Eigen::MatrixXd z_;                   // U^T B^T Y, (m - 1) x D
  Eigen::VectorXd z_energy_;            // squared norms of the rows of z_
};

// Fits the map with GCV's lambda in one call: the voice build's step 3.5.
RbfMap fit_rbf_by_gcv(const Eigen::MatrixXd& centres, const Eigen::MatrixXd& targets,
                      double r_squared, LambdaChoice* choice = nullptr);

}  // namespace fapcast
