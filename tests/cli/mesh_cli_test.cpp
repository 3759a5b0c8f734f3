// `fapcast expressions`, `adapt` and `render` end to end: outputs read back with the libraries'
// readers; bad input exits 1 naming the file and rule, bad usage exits 2, neither writes output.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/obj_mesh.hpp"
#include "fapcast/core/file_io.hpp"
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

namespace fapcast {
namespace {

namespace fs = std::filesystem;
using test::fapcast;
using test::run_command;

const std::string kIct = std::string(FAPCAST_SOURCE_DIR) + "/data/ict-facekit/generic_neutral_mesh.obj";

class MeshCli : public testing::Test {
 protected:
  void SetUp() override { dir_ = test::make_temp_dir("mesh"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string dir_;
};

struct Ppm {
  int width = 0, height = 0;
  std::string rgb;
};
Ppm read_ppm(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  Ppm p;
  std::string magic;
  int max = 0;
  in >> magic >> p.width >> p.height >> max;
  in.get();
  EXPECT_EQ(magic, "P6");
  EXPECT_EQ(max, 255);
  p.rgb.resize(static_cast<std::size_t>(p.width) * p.height * 3);
  in.read(p.rgb.data(), static_cast<std::streamsize>(p.rgb.size()));
  EXPECT_TRUE(in.good()) << file;
  return p;
}
double fraction_covered(const Ppm& p) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.rgb.size(); i += 3) n += p.rgb.compare(i, 3, "\x28\x28\x28") != 0;
  return static_cast<double>(n) / (p.rgb.size() / 3);
}
double fraction_different(const Ppm& a, const Ppm& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) n += a.rgb.compare(i, 3, b.rgb, i, 3) != 0;
  return static_cast<double>(n) / (a.rgb.size() / 3);
}

TEST_F(MeshCli, ExpressionsThenAdaptToAScaledFace) {
  const auto targets = dir_ + "/targets", adapted = dir_ + "/adapted";
  auto r = run_command(fapcast("expressions -o '" + targets + "' --intensity 50"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto generic = read_obj_mesh(kIct);
  const auto joy = read_obj_mesh(targets + "/joy.obj");
  require_same_topology(generic, kIct, joy, "joy.obj");
  EXPECT_GT((joy.vertices - generic.vertices).cwiseAbs().maxCoeff(), 0.05f);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(targets)) ++files;
  EXPECT_EQ(files, 6u);
  // Adapt two of them (keeps the test fast under the sanitizers).
  const auto two = dir_ + "/two";
  fs::create_directories(two);
  fs::copy_file(targets + "/joy.obj", two + "/joy.obj");
  fs::copy_file(targets + "/fear.obj", two + "/fear.obj");

  // The specific face: the generic one 1.5 times larger, moved.
  const Positions big = (1.5f * generic.vertices).colwise() + Eigen::Vector3f(1, 2, 3);
  write_file_atomically(dir_ + "/big.obj", write_obj_mesh(big, generic.faces));
  r = run_command(fapcast("adapt '" + two + "' '" + kIct + "' '" + dir_ + "/big.obj' -o '" + adapted + "'"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2 targets"), std::string::npos) << r.out;
  const auto big_joy = read_obj_mesh(adapted + "/joy.obj");
  const Positions want = big + 1.5f * (joy.vertices - generic.vertices);
  EXPECT_LT((big_joy.vertices - want).cwiseAbs().maxCoeff(), 1e-3f);
  EXPECT_EQ(big_joy.faces.face_vertices, generic.faces.face_vertices);
}

TEST_F(MeshCli, AdaptRefusesBadInputWithExitOneAndBadUsageWithTwo) {
  const auto targets = dir_ + "/targets", out = dir_ + "/out";
  fs::create_directories(targets);
  // A specific mesh with another topology: one triangle.
  write_file_atomically(dir_ + "/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write_file_atomically(targets + "/a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  auto r = run_command(fapcast("adapt '" + targets + "' '" + kIct + "' '" + dir_ + "/tri.obj' -o '" + out + "'"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("tri.obj"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("topology-mismatch"), std::string::npos) << r.err;
  // A bad OBJ line: file, line and rule.
  write_file_atomically(targets + "/b.obj", "v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n");
  r = run_command(fapcast("adapt '" + targets + "' '" + dir_ + "/tri.obj' '" + dir_ + "/tri.obj' -o '" + out + "'"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("b.obj:3"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("vertex-arity"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out + "/a.obj"));  // nothing written when any target is bad
  r = run_command(fapcast("adapt '" + targets + "' '" + kIct + "' -o '" + out + "'"));
  EXPECT_EQ(r.exit_code, 2);
  r = run_command(fapcast("render '" + dir_ + "/tri.obj' -o '" + out + "'"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("glb-container"), std::string::npos) << r.err;
}

TEST_F(MeshCli, ExpressionTourAsGlbWithObjFrames) {
  const auto glb = dir_ + "/tour.glb", frames = dir_ + "/frames";
  const auto r = run_command(fapcast("expressions -o '" + glb + "' --fps 20 --seconds 0.1 --obj-frames-out '" + frames + "'"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a = read_glb(read_file(glb), glb);
  EXPECT_EQ(a.targets_m.size(), 6u);
  EXPECT_EQ(a.target_names.front(), "joy");
  EXPECT_EQ(a.weights.rows(), 13);  // 6 expressions x 2 frames + the closing frame
  EXPECT_EQ(a.rate, (FrameRate{20, 1}));
  EXPECT_LT(a.base_positions_m.cwiseAbs().maxCoeff(), 0.5f);  // metres: a head, not 100 heads
  std::size_t objs = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(frames)) ++objs;
  EXPECT_EQ(objs, 13u);
  const auto frame1 = read_obj_mesh(frames + "/frame_000001.obj");
  EXPECT_LT((frame1.vertices - frame_positions(a, 1)).cwiseAbs().maxCoeff(), 1e-7f);
}

// The renderer draws a face that covers much of its view, and the open mouth differs visibly
// from the closed one.
TEST_F(MeshCli, RenderShowsTheMouthOpening) {
  const FaceModel& face = ict_face_model();
  Positions jaw = Positions::Zero(3, face.vertex_count());
  add_scaled(jaw, face.expressions[face.expression_index("jawOpen")], 1.0f);
  MorphAnimation a;
  a.base_positions_m = 0.01f * face.neutral_cm;
  a.triangles = triangulate(face.faces);
  a.targets_m = {0.01f * jaw};
  a.weights.resize(2, 1);
  a.weights << 0.0f, 1.0f;
  const auto glb = dir_ + "/jaw.glb";
  write_file_atomically(glb, write_glb(a));
  for (const std::string view : {"face", "mouth"}) {
    SCOPED_TRACE(view);
    const auto out = dir_ + "/" + view;
    const auto r = run_command(fapcast("render '" + glb + "' -o '" + out + "' --width 160 --view " + view));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto closed = read_ppm(out + "/frame_000000.ppm"), open = read_ppm(out + "/frame_000001.ppm");
    EXPECT_EQ(closed.width, 160);
    EXPECT_GT(fraction_covered(closed), 0.3);
    EXPECT_GT(fraction_different(closed, open), view == "mouth" ? 0.1 : 0.01);
  }
}

}  // namespace
}  // namespace fapcast
