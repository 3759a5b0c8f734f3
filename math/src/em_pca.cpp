#include "fapcast/math/em_pca.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

namespace fapcast {
namespace {

// Calls `visit(first, chunk)` for every chunk of the stream, in order; one buffer is reused.
template <class Visit>
void for_each_chunk(const FrameStream& frames, Eigen::Index chunk_frames, Eigen::MatrixXf& buffer,
                    Visit&& visit) {
  for (Eigen::Index first = 0; first < frames.frame_count; first += chunk_frames) {
    const Eigen::Index c = std::min(chunk_frames, frames.frame_count - first);
    Eigen::Ref<Eigen::MatrixXf> chunk = buffer.leftCols(c);
    frames.read(first, chunk);
    visit(first, chunk);
  }
}

Eigen::VectorXd stream_mean(const FrameStream& frames, Eigen::Index chunk_frames,
                            Eigen::MatrixXf& buffer) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(frames.dimension);
  for_each_chunk(frames, chunk_frames, buffer, [&](Eigen::Index, Eigen::Ref<Eigen::MatrixXf> chunk) {
    sum += chunk.cast<double>().rowwise().sum();
  });
  return sum / static_cast<double>(frames.frame_count);
}

// Sine of the largest principal angle between two orthonormal D x k bases.
double largest_angle_sine(const Eigen::MatrixXd& qa, const Eigen::MatrixXd& qb) {
  const Eigen::VectorXd cosines =
      Eigen::JacobiSVD<Eigen::MatrixXd>(qa.transpose() * qb).singularValues();
  const double c = std::clamp(cosines.minCoeff(), 0.0, 1.0);
  return std::sqrt(std::max(0.0, 1.0 - c * c));
}

}  // namespace

PcaBasis em_pca(const FrameStream& frames, const EmPcaOptions& options) {
  const Eigen::Index dim = frames.dimension;
  const Eigen::Index k = options.components;
  if (!frames.read || frames.frame_count < 1 || dim < 1) {
    throw std::invalid_argument("em_pca: empty frame stream");
  }
  if (k < 1 || k > dim || k > frames.frame_count) {
    throw std::invalid_argument("em_pca: k = " + std::to_string(k) + " outside [1, min(D, frames)]");
  }
  if (options.chunk_frames < 1 || options.max_iterations < 1) {
    throw std::invalid_argument("em_pca: chunk_frames and max_iterations must be >= 1");
  }
  const Eigen::Index chunk_frames = std::min(options.chunk_frames, frames.frame_count);
  Eigen::MatrixXf buffer(dim, chunk_frames);

  PcaBasis basis;
  basis.mean = stream_mean(frames, chunk_frames, buffer);

  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd start(dim, k);
  for (Eigen::Index j = 0; j < k; ++j) {
    for (Eigen::Index i = 0; i < dim; ++i) start(i, j) = normal(rng);
  }
  Eigen::MatrixXd c = orthonormal_basis(start);  // D x k, orthonormal

  Eigen::MatrixXd yx(dim, k);  // sum over frames of y x^T
  Eigen::MatrixXd xx(k, k);    // sum over frames of x x^T
  Eigen::MatrixXd y(dim, chunk_frames);
  Eigen::MatrixXd x(k, chunk_frames);
  basis.converged = false;
  for (int it = 1; it <= options.max_iterations; ++it) {
    yx.setZero();
    xx.setZero();
    double total = 0.0;
    for_each_chunk(frames, chunk_frames, buffer, [&](Eigen::Index, Eigen::Ref<Eigen::MatrixXf> chunk) {
      // Double arithmetic from here on: float32 products put a noise floor near 1e-7 of the top
      // variance, above the variance of the last of the 17 components on smooth data.
      auto yc = y.leftCols(chunk.cols());
      auto xc = x.leftCols(chunk.cols());
      yc = chunk.cast<double>().colwise() - basis.mean;
      xc.noalias() = c.transpose() * yc;   // E-step (C orthonormal: C^T C = I)
      yx.noalias() += yc * xc.transpose();  // M-step sums
      xx.noalias() += xc * xc.transpose();
      total += yc.squaredNorm();
    });
    basis.iterations = it;
    basis.total_variance = total / static_cast<double>(frames.frame_count);

    // M-step: C_new = YX^T (XX^T)^-1; its span is what counts, so orthonormalise it.
    const Eigen::MatrixXd c_new = orthonormal_basis(yx * xx.ldlt().solve(Eigen::MatrixXd::Identity(k, k)));
    const double moved = largest_angle_sine(c, c_new);
    if (options.on_iteration) options.on_iteration(it, moved);
    if (moved < options.tolerance) {
      basis.converged = true;
      break;  // keep c: xx was measured exactly for it, so the rotation below is exact
    }
    if (it < options.max_iterations) c = c_new;
  }
  // Rayleigh-Ritz inside the subspace of c: the k x k covariance of the coefficients measured in
  // the last pass, eigen-decomposed, orders the components by variance.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(xx / static_cast<double>(frames.frame_count));
  const Eigen::MatrixXd rotation = eig.eigenvectors().rowwise().reverse();  // descending
  basis.components = c * rotation;
  basis.variances = eig.eigenvalues().reverse().cwiseMax(0.0);
  return basis;
}

}  // namespace fapcast
