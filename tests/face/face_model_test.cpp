#include "fapcast/face/face_model.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/data_root.hpp"
#include "fapcast/face/marker_map.hpp"

namespace fapcast {
namespace {

const FaceModel& face() { return ict_face_model(); }

TEST(FaceModel, LoadsTheIctGenericFace) {
  EXPECT_EQ(face().vertex_count(), 26719);
  EXPECT_EQ(face().faces.size(), 26384u);
  EXPECT_EQ(face().expressions.size(), 53u);
  EXPECT_EQ(face().expression_names.size(), 53u);
  EXPECT_EQ(face().identities.size(), 10u);
  EXPECT_EQ(face().expression_names.front(), "browDown_L");
  EXPECT_NO_THROW((void)face().expression_index("jawOpen"));
  EXPECT_THROW((void)face().expression_index("jawClose"), std::out_of_range);
  // ICT is in cm: a head about 25 cm wide.
  const float width = face().neutral_cm.row(0).maxCoeff() - face().neutral_cm.row(0).minCoeff();
  EXPECT_GT(width, 20.0f);
  EXPECT_LT(width, 30.0f);
}

TEST(FaceModel, DeltaIndicesAreInRangeAndIncreasing) {
  for (const auto* set : {&face().expressions, &face().identities})
    for (const auto& d : *set) {
      ASSERT_FALSE(d.vertices.empty());
      EXPECT_EQ(static_cast<Eigen::Index>(d.vertices.size()), d.offsets_cm.cols());
      EXPECT_GE(d.vertices.front(), 0);
      EXPECT_LT(d.vertices.back(), face().vertex_count());
      EXPECT_TRUE(std::is_sorted(d.vertices.begin(), d.vertices.end()));
      EXPECT_TRUE(std::adjacent_find(d.vertices.begin(), d.vertices.end()) == d.vertices.end());
    }
}

TEST(FaceModel, FacesIndexExistingVertices) {
  const auto& f = face().faces;
  for (const auto v : f.face_vertices) {
    ASSERT_GE(v, 0);
    ASSERT_LT(v, face().vertex_count());
  }
  std::size_t expected = 0;
  for (std::size_t i = 0; i < f.size(); ++i) expected += f.face_starts[i + 1] - f.face_starts[i] - 2;
  const Eigen::Matrix3Xi tris = triangulate(f);
  EXPECT_EQ(static_cast<std::size_t>(tris.cols()), expected);
  EXPECT_GT(tris.cols(), static_cast<Eigen::Index>(f.size()));  // ICT is mostly quads
}

// Blending is linear in the weights: blend(a + b) - neutral = (blend(a) - n) + (blend(b) - n).
TEST(FaceModel, BlendIsLinearInTheWeights) {
  const auto k = face().expressions.size();
  std::vector<float> a(k, 0.0f), b(k, 0.0f), sum(k, 0.0f);
  a[face().expression_index("jawOpen")] = 0.4f;
  a[face().expression_index("mouthPucker")] = 0.7f;
  b[face().expression_index("jawOpen")] = 0.3f;
  b[face().expression_index("mouthSmile_L")] = 0.5f;
  for (std::size_t i = 0; i < k; ++i) sum[i] = a[i] + b[i];
  const Positions& n = face().neutral_cm;
  const Positions lhs = blend(n, face().expressions, sum) - n;
  const Positions rhs = (blend(n, face().expressions, a) - n) + (blend(n, face().expressions, b) - n);
  EXPECT_LT((lhs - rhs).cwiseAbs().maxCoeff(), 1e-5f);
  // Zero weights give the neutral face exactly.
  EXPECT_EQ(blend(n, face().expressions, std::vector<float>(k, 0.0f)), n);
}

// The sparse blend agrees with a dense reference (every vertex, every shape).
TEST(FaceModel, SparseBlendEqualsDenseBlend) {
  const auto k = face().expressions.size();
  std::vector<float> w(k);
  for (std::size_t i = 0; i < k; ++i) w[i] = static_cast<float>((i * 37) % 11) / 10.0f;
  Positions dense = face().neutral_cm;
  for (std::size_t i = 0; i < k; ++i) {
    Positions full = Positions::Zero(3, face().vertex_count());
    const auto& d = face().expressions[i];
    for (std::size_t j = 0; j < d.vertices.size(); ++j) full.col(d.vertices[j]) = d.offsets_cm.col(static_cast<Eigen::Index>(j));
    dense += w[i] * full;
  }
  EXPECT_LT((blend(face().neutral_cm, face().expressions, w) - dense).cwiseAbs().maxCoeff(), 1e-5f);
  EXPECT_THROW((void)blend(face().neutral_cm, face().expressions, std::vector<float>(3)),
               std::invalid_argument);
}

TEST(FaceModel, ActorIsNotTheGenericFace) {
  const std::vector<float> mix{0.6f, 0.0f, -0.4f, 0.3f};
  const FaceModel actor = make_actor(face(), mix);
  const float moved = (actor.neutral_cm - face().neutral_cm).colwise().norm().maxCoeff();
  EXPECT_GT(moved, 0.2f);  // cm: a visibly different face
  Positions expected = face().neutral_cm;
  for (std::size_t i = 0; i < mix.size(); ++i) add_scaled(expected, face().identities[i], mix[i]);
  EXPECT_LT((actor.neutral_cm - expected).cwiseAbs().maxCoeff(), 1e-6f);
  EXPECT_EQ(actor.expressions.size(), face().expressions.size());
  EXPECT_THROW((void)make_actor(face(), std::vector<float>(11, 0.1f)), std::invalid_argument);
}

TEST(FaceModel, DataRootFollowsTheEnvironment) {
  const auto fallback = data_root();
  EXPECT_TRUE(std::filesystem::exists(fallback / "ict-facekit" / "LICENSE"));
  ::setenv("FAPCAST_DATA", "/nonexistent/fapcast-data", 1);
  EXPECT_EQ(data_root(), std::filesystem::path("/nonexistent/fapcast-data"));
  ::unsetenv("FAPCAST_DATA");
  EXPECT_EQ(data_root(), fallback);
}

// Named bad inputs (meshes, targets, spec tables): each file's name states the rule it breaks; golden list in expected_errors.txt.
struct BadInput {
  std::string file;
  std::string expected;  // "line: rule"
};

std::vector<BadInput> bad_inputs() {
  std::vector<BadInput> out;
  std::ifstream in(std::string(FAPCAST_TEST_DATA) + "/synth/bad/expected_errors.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    out.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return out;
}

class FaceDataBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(FaceDataBadInput, IsRefusedWithFileLineAndRule) {
  const auto path = std::filesystem::path(FAPCAST_TEST_DATA) / "synth" / "bad" / GetParam().file;
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const auto ext = path.extension();
  try {
    if (ext == ".obj") (void)read_obj_mesh(path);
    else if (ext == ".target") (void)read_sparse_delta(path, 100);
    else if (ext == ".tsv") (void)read_marker_spec(path);
    else FAIL() << "no reader for " << path;
    FAIL() << "accepted " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(std::to_string(e.line()) + ": " + e.rule(), GetParam().expected) << e.what();
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Golden, FaceDataBadInput, ::testing::ValuesIn(bad_inputs()),
                         [](const auto& info) {
                           std::string n = info.param.file;
                           for (auto& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(FaceDataBadInput, GoldenListCoversEveryBadFile) {
  std::set<std::string> listed;
  for (const auto& b : bad_inputs()) listed.insert(b.file);
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(FAPCAST_TEST_DATA) + "/synth/bad"))
    if (e.path().filename().string().rfind("bad.", 0) == 0) {
      ++files;
      EXPECT_TRUE(listed.count(e.path().filename().string())) << e.path();
    }
  EXPECT_EQ(files, listed.size());
  EXPECT_GE(files, 8u);
}

}  // namespace
}  // namespace fapcast
