// adapt_voice on hand-made voices: a scaled and moved specific face scales every target-space
// quantity exactly and leaves the rest byte for byte; maps compose over two re-targets; a generic
// mesh that is not the voice's face is refused naming the feature point.
#include "fapcast/voice/voice_adaptation.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "fapcast/core/file_io.hpp"
#include "support/tiny_voice.hpp"

namespace fapcast {
namespace {

namespace vs = voice_section;
using fapcast::test::TinyVoice;

// TinyVoice's three vertices as a triangle whose vertex 0 is feature point 8.1's neutral spot.
Positions tiny_face() {
  Positions p(3, 3);
  p << 0.0f, 0.05f, -0.05f,  //
      -0.02f, 0.01f, 0.01f,  //
      0.1f, 0.09f, 0.09f;
  return p;
}
PolygonFaces one_triangle() {
  PolygonFaces f;
  f.face_vertices = {0, 1, 2};
  f.face_starts = {0, 3};
  return f;
}

Voice open_bytes(const std::string& bytes, const std::string& name) {
  const auto file = std::filesystem::temp_directory_path() / name;
  write_file_atomically(file, bytes);
  return Voice::open(file);
}

// The lip-contact term's shape is a target-space displacement, scaled like the RBF weights; its
// amounts (LCON) are the generic face's and carry over byte for byte, so the adapted voice closes
// the lips by the same amount of the (scaled) shape.
TEST(VoiceAdaptation, TheLipContactShapeIsAdaptedAndItsAmountsKept) {
  TinyVoice tiny;
  tiny.set_inner_lips_with_contact();
  const Positions generic = tiny_face();
  const std::vector<VoiceFeaturePoint> points = {{"2.2", 0, generic.col(0).cast<double>()},
                                                 {"2.3", 1, generic.col(1).cast<double>()}};
  const std::vector<VoiceRigidMarker> rigid = {{"H.temple_l", 0, generic.col(0).cast<double>(), {0.07, 0.03, 0.01}},
                                               {"H.temple_r", 1, generic.col(1).cast<double>(), {-0.07, 0.03, 0.01}},
                                               {"H.nose_bridge", 2, generic.col(2).cast<double>(), {0.0, 0.04, 0.1}}};
  tiny.feature_points = voice_feature_points_json(points, rigid);
  const Voice voice = open_bytes(tiny.bytes(), "fapcast_retarget_contact_in.fapv");
  const float s = 2.0f;
  const Voice v2 = open_bytes(adapt_voice(voice, generic, s * generic, one_triangle(), "twice.obj").bytes,
                              "fapcast_retarget_contact_out.fapv");
  EXPECT_LT((v2.file().matrix_f32(vs::kLipContactShape) - s * voice.file().matrix_f32(vs::kLipContactShape))
                .cwiseAbs().maxCoeff(), 1e-7f);
  const auto a = voice.file().bytes(vs::kLipContact), b = v2.file().bytes(vs::kLipContact);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin()));
  Eigen::VectorXd touching = Eigen::VectorXd::Zero(6);
  touching(4) = -0.0005;  // the source's lips at their contact
  EXPECT_NEAR(v2.retargeting().responses(touching)(2), voice.retargeting().responses(touching)(2), 1e-12);
}

TEST(VoiceAdaptation, AScaledFaceScalesEveryTargetQuantityExactly) {
  const Voice voice = open_bytes(TinyVoice().bytes(), "fapcast_retarget_in.fapv");
  const Positions generic = tiny_face();
  const float s = 1.5f;
  const Eigen::Vector3f t(0.01f, -0.02f, 0.03f);
  const Positions specific = (s * generic).colwise() + t;
  const AdaptedVoice out = adapt_voice(voice, generic, specific, one_triangle(), "big.obj");
  EXPECT_EQ(out.summary.vertices, 3u);
  EXPECT_EQ(out.summary.triangles, 1u);
  const Voice v2 = open_bytes(out.bytes, "fapcast_retarget_out.fapv");

  // Mean: specific + s (mean - generic); components and RBF weights: s times.
  const Eigen::Map<const Positions> mean(voice.pca_mean().data(), 3, 3), mean2(v2.pca_mean().data(), 3, 3);
  EXPECT_LT((mean2 - (specific + s * (mean - generic))).cwiseAbs().maxCoeff(), 1e-5f);
  EXPECT_LT((v2.pca_components() - s * voice.pca_components()).cwiseAbs().maxCoeff(), 1e-6f);
  EXPECT_LT((v2.file().matrix_f32(vs::kRbfWeights) - s * voice.file().matrix_f32(vs::kRbfWeights)).cwiseAbs().maxCoeff(),
            1e-6f);
  // The feature point now sits on the specific neutral; the source side is unchanged.
  EXPECT_LT((v2.feature_points()[0].neutral_m - specific.col(0).cast<double>()).norm(), 1e-7);
  EXPECT_EQ(v2.rigid_markers()[1].source_reference_m, voice.rigid_markers()[1].source_reference_m);
  // Face maps: s I.
  ASSERT_TRUE(v2.face_maps().has_value());
  const Eigen::Matrix3f identity = Eigen::Matrix3f::Identity();
  for (Eigen::Index i = 0; i < 3; ++i)
    EXPECT_LT((v2.face_maps()->row(i) - s * Eigen::RowVectorXf::Map(identity.data(), 9)).cwiseAbs().maxCoeff(), 1e-6f);
  // Untouched sections: byte for byte.
  for (const SectionId id : {vs::kPcaVariances, vs::kFrameCoefficients, vs::kRbfCentres, vs::kRbfScalars,
                             vs::kPhoneGraph}) {
    const auto a = voice.file().bytes(id), b = v2.file().bytes(id);
    ASSERT_EQ(a.size(), b.size()) << id.str();
    EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin())) << id.str();
  }
  EXPECT_NE(v2.provenance().target_face.find("re-targeted to big.obj"), std::string::npos);

  // A second re-target (from the specific face, scale 2 more) composes the maps: 3 I.
  const Positions bigger = 2.0f * specific;
  const Voice v3 = open_bytes(adapt_voice(v2, specific, bigger, one_triangle(), "bigger.obj").bytes,
                              "fapcast_retarget_out2.fapv");
  EXPECT_NEAR((*v3.face_maps())(1, 4), 2 * s, 1e-5f);  // row 1's yy entry
  EXPECT_NEAR((*v3.face_maps())(1, 1), 0.0f, 1e-5f);
  EXPECT_LT((v3.pca_components() - 2 * s * voice.pca_components()).cwiseAbs().maxCoeff(), 1e-5f);
}

TEST(VoiceAdaptation, RefusesAGenericMeshThatIsNotTheVoicesFace) {
  const Voice voice = open_bytes(TinyVoice().bytes(), "fapcast_retarget_bad.fapv");
  const Positions cm = 100.0f * tiny_face();  // the right face in the wrong unit
  try {
    (void)adapt_voice(voice, cm, cm, one_triangle(), "s.obj");
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("generic-mismatch: feature point 8.1 (vertex 0)"), std::string::npos)
        << e.what();
  }
  const Positions four = Positions::Zero(3, 4);
  EXPECT_THROW((void)adapt_voice(voice, four, four, one_triangle(), "s.obj"), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
