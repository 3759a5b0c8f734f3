#pragma once
// Eigen matrix types the libraries share by name.
#include <Eigen/Core>

namespace fapcast {

// Row-major float matrix: a PCA basis or a run of frames stored frame after frame (k x D, F x k),
// the layout of the voice file's sections and of the FAP basis.
using RowMajorMatrixXf = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

}  // namespace fapcast
