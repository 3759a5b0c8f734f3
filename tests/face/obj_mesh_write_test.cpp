// OBJ writing: exact round trip through the reader, and the topology check's refusals.
#include <gtest/gtest.h>

#include <fstream>

#include "fapcast/core/input_error.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/obj_mesh.hpp"
#include "support/run_command.hpp"

namespace fapcast {
namespace {

ObjMesh write_and_read(const Positions& v, const PolygonFaces& f, const std::string& dir) {
  const auto path = dir + "/mesh.obj";
  std::ofstream(path) << write_obj_mesh(v, f, "round trip");
  return read_obj_mesh(path);
}

TEST(ObjMeshWrite, IctFaceRoundTripsExactly) {
  const auto dir = test::make_temp_dir("objwrite");
  const FaceModel& face = ict_face_model();
  const ObjMesh back = write_and_read(face.neutral_cm, face.faces, dir);
  EXPECT_EQ(back.vertices, face.neutral_cm);  // shortest round-trip text: bit-exact
  EXPECT_EQ(back.faces.face_starts, face.faces.face_starts);
  EXPECT_EQ(back.faces.face_vertices, face.faces.face_vertices);
  EXPECT_NO_THROW(require_same_topology(ObjMesh{face.neutral_cm, face.faces}, "g.obj", back, "s.obj"));
  std::filesystem::remove_all(dir);
}

TEST(ObjMeshWrite, TopologyMismatchNamesTheFileAndTheFirstDifference) {
  ObjMesh a;
  a.vertices = Positions::Random(3, 4);
  a.faces.face_vertices = {0, 1, 2, 0, 2, 3};
  a.faces.face_starts = {0, 3, 6};
  ObjMesh fewer = a;
  fewer.vertices.conservativeResize(3, 3);
  ObjMesh other = a;
  other.faces.face_vertices[4] = 1;
  ObjMesh quad = a;
  quad.faces.face_vertices = {0, 1, 2, 3};
  quad.faces.face_starts = {0, 4};
  const auto expect = [&](const ObjMesh& s, const std::string& detail) {
    try {
      require_same_topology(a, "generic.obj", s, "specific.obj");
      FAIL() << "accepted " << detail;
    } catch (const InputError& e) {
      EXPECT_EQ(e.rule(), "topology-mismatch");
      EXPECT_EQ(e.where().source, "specific.obj");
      EXPECT_NE(std::string(e.what()).find(detail), std::string::npos) << e.what();
    }
  };
  expect(fewer, "3 vertices, expected 4");
  expect(other, "face 2 has other corners");
  expect(quad, "1 faces, expected 2");
}

}  // namespace
}  // namespace fapcast
