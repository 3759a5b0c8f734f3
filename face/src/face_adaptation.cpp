#include "fapcast/face/face_adaptation.hpp"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fapcast/face/obj_mesh.hpp"

namespace fapcast {
namespace {

// Connectivity only: the positions stay in Eigen (double for the maps); OpenMesh gives the
// vertex -> triangle adjacency and refuses non-manifold input.
struct Traits : OpenMesh::DefaultTraits {};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

// A generic triangle with area <= kDegenerateArea * (mean squared radius about the centroid) is
// degenerate: relative, so the test is the same at any scale; 1e-12 lies far below ICT's
// smallest triangles (~1e-6) and far above float rounding of collinear corners (~1e-14).
constexpr double kDegenerateArea = 1e-12;

// The face normal scaled to length sqrt(|n|): it then grows like an edge under scaling, so a
// uniform scale s maps to exactly s I (deformation transfer's fourth vertex).
Eigen::Vector3d scaled_normal(const Eigen::Vector3d& e1, const Eigen::Vector3d& e2) {
  const Eigen::Vector3d n = e1.cross(e2);
  const double length = n.norm();
  return length > 0 ? Eigen::Vector3d(n / std::sqrt(length)) : Eigen::Vector3d::Zero();
}

std::string triangle_text(std::size_t t, int a, int b, int c) {
  return "triangle " + std::to_string(t) + " (vertices " + std::to_string(a) + " " +
         std::to_string(b) + " " + std::to_string(c) + ", 0-based)";
}

}  // namespace

Eigen::Matrix3d triangle_map(const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                             const Eigen::Vector3d& x3, const Eigen::Vector3d& y1,
                             const Eigen::Vector3d& y2, const Eigen::Vector3d& y3) {
  Eigen::Matrix3d generic, specific;
  generic << x2 - x1, x3 - x1, scaled_normal(x2 - x1, x3 - x1);
  specific << y2 - y1, y3 - y1, scaled_normal(y2 - y1, y3 - y1);
  // generic's determinant is |n|^1.5 > 0 for a non-degenerate triangle: the frame is invertible.
  return specific * generic.inverse();
}

FaceAdaptation::FaceAdaptation(const Positions& generic, const Positions& specific,
                               const PolygonFaces& faces) {
  const Eigen::Index n = generic.cols();
  if (specific.cols() != n)
    throw std::invalid_argument("adaptation: generic mesh has " + std::to_string(n) +
                                " vertices, specific mesh " + std::to_string(specific.cols()));
  for (const auto v : faces.face_vertices)
    if (v < 0 || v >= n)
      throw std::invalid_argument("adaptation: face vertex index " + std::to_string(v) +
                                  " outside 0.." + std::to_string(n - 1));
  const Eigen::Matrix3Xd x = generic.cast<double>();
  const Eigen::Matrix3Xd y = specific.cast<double>();

  // Global linear map about the centroids (the paper's "relative to the model's centre"):
  // argmin_A sum |y_c - A x_c|^2 = (Y X^T)(X X^T)^-1; exact for a global scale or rotation.
  const Eigen::Vector3d x_centre = x.rowwise().mean();
  const Eigen::Vector3d y_centre = y.rowwise().mean();
  const Eigen::Matrix3Xd xc = x.colwise() - x_centre;
  const Eigen::Matrix3Xd yc = y.colwise() - y_centre;
  const Eigen::Matrix3d xx = xc * xc.transpose();
  if (n > 0 && xx.fullPivLu().isInvertible()) global_map_ = (yc * xc.transpose()) * xx.inverse();
  const double mean_square_radius = n > 0 ? xc.squaredNorm() / static_cast<double>(n) : 0.0;

  const Eigen::Matrix3Xi triangles = triangulate(faces);
  triangle_count_ = static_cast<std::size_t>(triangles.cols());
  TriMesh mesh;
  mesh.reserve(static_cast<std::size_t>(n), 3 * triangle_count_, triangle_count_);
  std::vector<TriMesh::VertexHandle> handles(static_cast<std::size_t>(n));
  for (auto& h : handles) h = mesh.add_vertex(TriMesh::Point(0, 0, 0));
  // Per triangle: its map and its weight; OpenMesh face index -> triangle index.
  std::vector<Eigen::Matrix3d> triangle_maps(triangle_count_);
  std::vector<double> weights(triangle_count_, 0.0);
  std::vector<std::size_t> triangle_of_face;
  triangle_of_face.reserve(triangle_count_);
  {
    // OpenMesh reports refused faces on its error stream; our exception says it instead.
    omerr().disable();
    for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
      const int a = triangles(0, t), b = triangles(1, t), c = triangles(2, t);
      if (a == b || b == c || a == c) continue;  // a repeated corner: degenerate, weight 0
      const auto face = mesh.add_face(handles[static_cast<std::size_t>(a)],
                                      handles[static_cast<std::size_t>(b)],
                                      handles[static_cast<std::size_t>(c)]);
      if (!face.is_valid()) {
        omerr().enable();
        throw std::invalid_argument("adaptation: " +
                                    triangle_text(static_cast<std::size_t>(t), a, b, c) +
                                    " makes the mesh non-manifold (an edge shared by more "
                                    "than two triangles, or flipped orientation)");
      }
      triangle_of_face.push_back(static_cast<std::size_t>(t));
    }
    omerr().enable();
  }
  for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
    const int a = triangles(0, t), b = triangles(1, t), c = triangles(2, t);
    const double area = 0.5 * (x.col(b) - x.col(a)).cross(x.col(c) - x.col(a)).norm();
    const auto i = static_cast<std::size_t>(t);
    if (!(area > kDegenerateArea * mean_square_radius)) {
      ++degenerate_triangle_count_;
      continue;
    }
    triangle_maps[i] = triangle_map(x.col(a), x.col(b), x.col(c), y.col(a), y.col(b), y.col(c));
    weights[i] = area;
  }

  maps_.resize(static_cast<std::size_t>(n));
  for (const auto vh : mesh.vertices()) {
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
    double weight = 0.0;
    for (const auto fh : mesh.vf_range(vh)) {
      const auto f = triangle_of_face[static_cast<std::size_t>(fh.idx())];
      if (weights[f] == 0.0) continue;
      sum += weights[f] * triangle_maps[f];
      weight += weights[f];
    }
    const auto i = static_cast<std::size_t>(vh.idx());
    if (weight > 0.0) {
      maps_[i] = (sum / weight).cast<float>();
    } else {
      maps_[i] = global_map_.cast<float>();
      ++global_map_vertex_count_;
    }
  }
}

Positions FaceAdaptation::adapt(const Positions& generic_displacements) const {
  if (generic_displacements.cols() != vertex_count())
    throw std::invalid_argument("adaptation: displacements for " +
                                std::to_string(generic_displacements.cols()) +
                                " vertices, meshes have " + std::to_string(vertex_count()));
  Positions out(3, generic_displacements.cols());
  for (Eigen::Index i = 0; i < out.cols(); ++i)
    out.col(i) = maps_[static_cast<std::size_t>(i)] * generic_displacements.col(i);
  return out;
}

SparseDelta FaceAdaptation::adapt(const SparseDelta& generic_delta) const {
  SparseDelta out{generic_delta.vertices, Positions(3, generic_delta.offsets_cm.cols())};
  for (std::size_t k = 0; k < generic_delta.vertices.size(); ++k) {
    const auto v = generic_delta.vertices[k];
    if (v < 0 || v >= vertex_count())
      throw std::invalid_argument("adaptation: target moves vertex " + std::to_string(v) +
                                  ", meshes have " + std::to_string(vertex_count()));
    const auto col = static_cast<Eigen::Index>(k);
    out.offsets_cm.col(col) = maps_[static_cast<std::size_t>(v)] * generic_delta.offsets_cm.col(col);
  }
  return out;
}

}  // namespace fapcast
