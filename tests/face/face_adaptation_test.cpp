// Model adaptation (spec/adaptation.md): properties the maps must have on the ICT face and on
// small hand-made meshes, and agreement with an independent implementation that needs no
// OpenMesh (a plain scatter over the triangles).
#include "fapcast/face/face_adaptation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "fapcast/face/face_model.hpp"
#include "fapcast/face/obj_mesh.hpp"
#include "support/scatter_adaptation.hpp"

namespace fapcast {
namespace {

const FaceModel& ict() { return ict_face_model(); }

// The largest |entry| of the difference of two matrices.
double max_abs(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

// The ICT jawOpen target as a dense 3 x N displacement.
Positions jaw_open() {
  Positions d = Positions::Zero(3, ict().vertex_count());
  add_scaled(d, ict().expressions[ict().expression_index("jawOpen")], 1.0f);
  return d;
}

TEST(TriangleMap, MeetsItsEdgeConstraintsForAnyTriangles) {
  const Eigen::Vector3d x1(0.1, 0.2, 0.3), x2(1.3, -0.2, 0.5), x3(0.4, 0.9, -0.6);
  const Eigen::Vector3d y1(2.0, 1.0, 0.0), y2(2.5, 3.0, 1.0), y3(-1.0, 0.7, 0.2);
  const Eigen::Matrix3d a = triangle_map(x1, x2, x3, y1, y2, y3);
  EXPECT_LT((a * (x2 - x1) - (y2 - y1)).norm(), 1e-12);
  EXPECT_LT((a * (x3 - x1) - (y3 - y1)).norm(), 1e-12);
  // The normal frame: A n_x / sqrt|n_x| = n_y / sqrt|n_y|.
  const Eigen::Vector3d nx = (x2 - x1).cross(x3 - x1), ny = (y2 - y1).cross(y3 - y1);
  EXPECT_LT((a * nx / std::sqrt(nx.norm()) - ny / std::sqrt(ny.norm())).norm(), 1e-12);
}

TEST(TriangleMap, IsExactlyASimilarityWhenTheTriangleIsMovedByOne) {
  const Eigen::Vector3d x1(0.1, 0.2, 0.3), x2(1.3, -0.2, 0.5), x3(0.4, 0.9, -0.6);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (const double s : {1e-8, 0.5, 1.0, 3.0, 1e8}) {
    SCOPED_TRACE(s);
    const Eigen::Vector3d t(5, -2, 1);  // moved too, at the same scale
    const auto y = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return s * (r * x + t); };
    const Eigen::Matrix3d a = triangle_map(x1, x2, x3, y(x1), y(x2), y(x3));
    EXPECT_LT(max_abs(a / s, r), 1e-9);
  }
}

TEST(FaceAdaptation, IdenticalModelsGiveIdentityMaps) {
  const FaceAdaptation adaptation(ict().neutral_cm, ict().neutral_cm, ict().faces);
  EXPECT_EQ(adaptation.vertex_count(), ict().vertex_count());
  EXPECT_EQ(adaptation.triangle_count(), static_cast<std::size_t>(triangulate(ict().faces).cols()));
  EXPECT_EQ(adaptation.degenerate_triangle_count(), 0u);
  EXPECT_EQ(adaptation.global_map_vertex_count(), 0u);
  double worst = 0;
  for (std::int32_t i = 0; i < adaptation.vertex_count(); ++i)
    worst = std::max(worst, max_abs(adaptation.vertex_map(i).cast<double>(), Eigen::Matrix3d::Identity()));
  EXPECT_LT(worst, 1e-5);
  const Positions d = jaw_open();
  EXPECT_LT((adaptation.adapt(d) - d).cwiseAbs().maxCoeff(), 1e-5f * d.cwiseAbs().maxCoeff());
  EXPECT_LT(max_abs(adaptation.global_map(), Eigen::Matrix3d::Identity()), 1e-9);
}

// The first `count` faces of the ICT face (the other vertices then take the global map): keeps
// the tests that build several adaptations fast under the sanitizers.
PolygonFaces ict_patch(std::size_t count) {
  PolygonFaces patch;
  const auto& f = ict().faces;
  patch.face_starts.assign(f.face_starts.begin(), f.face_starts.begin() + static_cast<std::ptrdiff_t>(count) + 1);
  patch.face_vertices.assign(f.face_vertices.begin(), f.face_vertices.begin() + patch.face_starts.back());
  return patch;
}

// A specific face that is the generic one scaled (and moved) receives exactly scaled motion,
// at everyday and extreme scales.
TEST(FaceAdaptation, GloballyScaledFaceReceivesScaledMotion) {
  const Positions d = jaw_open();
  const PolygonFaces patch = ict_patch(4000);
  for (const float s : {1e-6f, 1.3f, 1e6f}) {
    SCOPED_TRACE(s);
    const Positions specific = s * (ict().neutral_cm.colwise() + Eigen::Vector3f(4, -7, 2));
    const FaceAdaptation adaptation(ict().neutral_cm, specific, patch);
    EXPECT_GT(adaptation.global_map_vertex_count(), 0u);
    EXPECT_EQ(adaptation.degenerate_triangle_count(), 0u);
    const Positions adapted = adaptation.adapt(d);
    EXPECT_LT((adapted / s - d).cwiseAbs().maxCoeff(), 2e-5f * d.cwiseAbs().maxCoeff());
    EXPECT_LT(max_abs(adaptation.global_map() / s, Eigen::Matrix3d::Identity()), 1e-6);
  }
}

TEST(FaceAdaptation, RotatedFaceReceivesRotatedMotion) {
  const Eigen::Matrix3f r =
      Eigen::AngleAxisf(0.9f, Eigen::Vector3f(0.3f, 1.0f, -0.2f).normalized()).toRotationMatrix();
  const Positions specific = r * ict().neutral_cm;
  const FaceAdaptation adaptation(ict().neutral_cm, specific, ict().faces);
  const Positions d = jaw_open();
  const Positions adapted = adaptation.adapt(d);
  EXPECT_LT((adapted - r * d).cwiseAbs().maxCoeff(), 2e-5f * d.cwiseAbs().maxCoeff());
  double worst = 0;
  for (std::int32_t i = 0; i < adaptation.vertex_count(); ++i)
    worst = std::max(worst, max_abs(adaptation.vertex_map(i).cast<double>(), r.cast<double>()));
  EXPECT_LT(worst, 1e-4);
}

// A specific face made from ICT identity shapes, applied to the face's left half only (x > 0):
// vertices whose neighbourhood it does not move keep identity maps; elsewhere the motion
// changes, but adapting there and back again returns close to the start; and the two
// implementations agree.
TEST(FaceAdaptation, IctIdentityFaces) {
  const std::vector<float> weights{0.8f, -0.6f, 0.5f, 0.0f, 0.7f};
  FaceModel actor = make_actor(ict(), weights);
  for (Eigen::Index i = 0; i < actor.neutral_cm.cols(); ++i)
    if (ict().neutral_cm(0, i) <= 0.0f) actor.neutral_cm.col(i) = ict().neutral_cm.col(i);
  const FaceAdaptation there(ict().neutral_cm, actor.neutral_cm, ict().faces);
  const FaceAdaptation back(actor.neutral_cm, ict().neutral_cm, ict().faces);
  EXPECT_EQ(there.degenerate_triangle_count(), 0u);

  // Vertices the identity moves, and all their triangle neighbours.
  const Positions moved = actor.neutral_cm - ict().neutral_cm;
  std::vector<bool> touched(static_cast<std::size_t>(ict().vertex_count()), false);
  const auto tris = triangulate(ict().faces);
  for (Eigen::Index t = 0; t < tris.cols(); ++t) {
    bool any = false;
    for (int c = 0; c < 3; ++c) any = any || moved.col(tris(c, t)).squaredNorm() > 0.0f;
    if (any)
      for (int c = 0; c < 3; ++c) touched[static_cast<std::size_t>(tris(c, t))] = true;
  }
  std::size_t untouched = 0, changed = 0;
  const auto reference = test::scatter_adaptation_maps(ict().neutral_cm, actor.neutral_cm, ict().faces);
  double disagreement = 0, round_trip = 0;
  for (std::int32_t i = 0; i < there.vertex_count(); ++i) {
    const Eigen::Matrix3d a = there.vertex_map(i).cast<double>();
    ASSERT_TRUE(a.allFinite()) << i;
    disagreement = std::max(disagreement, max_abs(a, reference[static_cast<std::size_t>(i)]));
    round_trip += (back.vertex_map(i).cast<double>() * a - Eigen::Matrix3d::Identity()).norm();
    if (!touched[static_cast<std::size_t>(i)]) {
      ++untouched;
      EXPECT_LT(max_abs(a, Eigen::Matrix3d::Identity()), 1e-5) << i;
    } else if (max_abs(a, Eigen::Matrix3d::Identity()) > 1e-3) {
      ++changed;
    }
  }
  EXPECT_GT(untouched, 0u);
  EXPECT_GT(changed, 1000u);  // the identity reshapes most of the face
  EXPECT_LT(disagreement, 1e-5);
  EXPECT_LT(round_trip / there.vertex_count(), 0.05);  // mean |A_back A_there - I|_F

  // The adapted mouth opening differs from the generic one but keeps its size.
  const Positions d = jaw_open();
  const Positions adapted = there.adapt(d);
  EXPECT_GT((adapted - d).norm(), 1e-3f * d.norm());
  EXPECT_NEAR(adapted.norm() / d.norm(), 1.0f, 0.25f);

  // The sparse form moves the same vertices by the same amounts as the dense one.
  const SparseDelta& sparse = ict().expressions[ict().expression_index("jawOpen")];
  const SparseDelta adapted_sparse = there.adapt(sparse);
  ASSERT_EQ(adapted_sparse.vertices, sparse.vertices);
  for (std::size_t k = 0; k < sparse.vertices.size(); ++k)
    EXPECT_LT((adapted_sparse.offsets_cm.col(static_cast<Eigen::Index>(k)) -
               adapted.col(sparse.vertices[k])).norm(), 1e-6f);
}

// A small open mesh: a square of 4 triangles round a centre, then degenerate extras.
struct SmallMesh {
  Positions vertices;
  PolygonFaces faces;
  void add_face(std::initializer_list<std::int32_t> corners) {
    for (const auto c : corners) faces.face_vertices.push_back(c);
    faces.face_starts.push_back(static_cast<std::int32_t>(faces.face_vertices.size()));
  }
};

SmallMesh square_with_degenerate_triangles() {
  SmallMesh m;
  m.vertices.resize(3, 8);
  m.vertices << 0, 1, 1, -1, -1, 2, 3, 2.5,  //
      0, -1, 1, 1, -1, 0, 0, 0,                //
      1, 0.5, 0.5, 0.5, 0.5, 0, 0, 0;
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  m.add_face({0, 3, 4});
  m.add_face({0, 4, 1});
  m.add_face({5, 6, 7});  // collinear: zero area
  m.add_face({1, 6, 5});  // a proper triangle hanging off vertex 1
  return m;
}

TEST(FaceAdaptation, DegenerateTrianglesCarryNoWeight) {
  const SmallMesh m = square_with_degenerate_triangles();
  Positions specific = 2.0f * m.vertices;
  specific(2, 0) += 0.3f;  // lift the centre: a non-uniform change
  const FaceAdaptation a(m.vertices, specific, m.faces);
  EXPECT_EQ(a.triangle_count(), 6u);
  EXPECT_EQ(a.degenerate_triangle_count(), 1u);
  EXPECT_EQ(a.global_map_vertex_count(), 1u);  // vertex 7 touches only the collinear triangle
  for (std::int32_t i = 0; i < a.vertex_count(); ++i) EXPECT_TRUE(a.vertex_map(i).allFinite()) << i;
  EXPECT_LT(max_abs(a.vertex_map(7).cast<double>(), a.global_map()), 1e-6);
  // Vertices 5 and 6 see only the proper triangle (1 6 5), so its map.
  const Eigen::Matrix3d only = triangle_map(
      m.vertices.col(1).cast<double>(), m.vertices.col(6).cast<double>(), m.vertices.col(5).cast<double>(),
      specific.col(1).cast<double>(), specific.col(6).cast<double>(), specific.col(5).cast<double>());
  EXPECT_LT(max_abs(a.vertex_map(5).cast<double>(), only), 1e-6);
  EXPECT_LT(max_abs(a.vertex_map(6).cast<double>(), only), 1e-6);

  // A triangle with a repeated corner, or with two corners at one point, is degenerate too.
  SmallMesh n = square_with_degenerate_triangles();
  n.vertices.col(7) = n.vertices.col(6);
  n.add_face({2, 2, 3});
  const FaceAdaptation b(n.vertices, 2.0f * n.vertices, n.faces);
  EXPECT_EQ(b.degenerate_triangle_count(), 2u);
  for (std::int32_t i = 0; i < b.vertex_count(); ++i)
    EXPECT_LT(max_abs(b.vertex_map(i).cast<double>(), 2.0 * Eigen::Matrix3d::Identity()), 1e-6) << i;
}

TEST(FaceAdaptation, RefusesMismatchedAndNonManifoldMeshes) {
  const SmallMesh m = square_with_degenerate_triangles();
  EXPECT_THROW(FaceAdaptation(m.vertices, m.vertices.leftCols(7), m.faces), std::invalid_argument);
  SmallMesh bad = m;
  bad.add_face({0, 1, 9});
  EXPECT_THROW(FaceAdaptation(bad.vertices, bad.vertices, bad.faces), std::invalid_argument);
  SmallMesh fin = m;  // a third triangle on edge 0-1: not a 2-manifold
  fin.add_face({0, 1, 6});
  try {
    FaceAdaptation(fin.vertices, fin.vertices, fin.faces);
    FAIL() << "accepted a non-manifold mesh";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("triangle 6 (vertices 0 1 6"), std::string::npos) << e.what();
  }
  const FaceAdaptation ok(m.vertices, m.vertices, m.faces);
  EXPECT_THROW(ok.adapt(Positions::Zero(3, 5)), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
