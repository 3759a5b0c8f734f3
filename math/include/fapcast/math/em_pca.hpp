#pragma once
// EM-PCA (Roweis, "EM algorithms for PCA and SPCA", NIPS 1998) over a stream of frames, the
// compression of paper section 3.6: k components of D-dimensional frames (D = 3N = 80,157 for the
// ICT face, ~60,000 corpus frames) without ever holding all frames. Each iteration is one pass:
//   E-step  X = (C^T C)^-1 C^T Y        (k x chunk, per chunk of centred frames Y)
//   M-step  C = (sum Y X^T) (sum X X^T)^-1
// C is kept orthonormal between passes (this leaves EM's subspace sequence unchanged and makes the
// E-step a plain product). Memory: O(k D + D * chunk); the frames arrive as float32, the
// products and sums are double (float32 products cannot resolve the smallest of 17 variances).
#include <Eigen/Core>
#include <cstdint>
#include <functional>

#include "fapcast/math/pca_basis.hpp"

namespace fapcast {

// A corpus of frames read in chunks: `read(first, out)` fills the columns of `out` (dimension x
// c) with frames first .. first + c - 1. Called in order, several times (one pass per iteration).
struct FrameStream {
  Eigen::Index frame_count = 0;
  Eigen::Index dimension = 0;
  std::function<void(Eigen::Index first, Eigen::Ref<Eigen::MatrixXf> out)> read;
};

struct EmPcaOptions {
  int components = 17;            // k (paper: 17)
  int max_iterations = 300;       // passes after the mean pass
  double tolerance = 1e-5;        // stop when the subspace moves less (sine of largest angle)
  Eigen::Index chunk_frames = 128;
  std::uint64_t seed = 1;         // of the random start; the result is deterministic per seed
  // Called after each pass with the iteration number and how far the subspace moved (sine of
  // the largest principal angle): progress for `fapcast voice build`. May be empty.
  std::function<void(int iteration, double moved)> on_iteration;
};

// Runs EM-PCA over `frames`: 1 pass for the mean, then one per iteration. The returned components
// are the Rayleigh-Ritz rotation of the last subspace (orthonormal, by decreasing variance).
// Throws std::invalid_argument when k is not in [1, min(D, frames)] or the stream is empty.
PcaBasis em_pca(const FrameStream& frames, const EmPcaOptions& options = {});

}  // namespace fapcast
