#pragma once
// A hand-made complete voice for tests (Voice::open accepts it): small, or as wide as a real face.
#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fapcast/core/file_io.hpp"
#include "fapcast/voice/voice.hpp"
#include "fapcast/voice/voice_file.hpp"
#include "fapcast/voice/voice_graph.hpp"

namespace fapcast::test {

// The pieces of a tiny voice: D = 3 x vertices (3 by default), k components (1), m = centres
// (2) of d = 3 (one feature point, 8.1 at vertex 0), 3 frames in one utterance of two phone
// states. Tests change a piece and assemble. mean(i) = offset(i) = i; component r is 1 at
// coordinate r + 1; RBF weight row j is (-1)^j at coordinate 1 (vertex 0's y); centre j is
// (0, -0.01 j, 0). Set coefficients to 3 x k when k > 1.
struct TinyVoice {
  VoiceProvenance provenance;
  VoiceGraphData graph;
  std::string feature_points;
  RowMajorMatrixXf coefficients{{0.5f}, {-0.5f}, {0.f}};
  SectionId skip{"----"};
  Eigen::Index vertices = 3;
  Eigen::Index components = 1;
  Eigen::Index centres = 2;
  std::optional<RowMajorMatrixXf> face_maps;  // FMAP, vertices x 9, when set
  std::optional<RowMajorMatrixXf> pca_components;  // k x D instead of the shifted identity, when set
  std::optional<RowMajorMatrixXf> pca_variances;   // 1 x k instead of 0.25 each, when set
  Eigen::Index source_points = 1;  // feature points in feature_points: the RBF centres' width / 3
  // The lip-contact term: LCSH (1 x D) and LCON (1 x (5 + m)), each written when set.
  std::optional<RowMajorMatrixXf> lip_contact_shape;
  std::optional<RowMajorMatrixXd> lip_contact;

  TinyVoice() {
    provenance.corpus = "hand-made";
    provenance.target_face = "three-vertex test face";
    provenance.seed = 3;
    provenance.synthetic = true;
    provenance.build_time_utc = "2026-11-22T04:00:00Z";
    provenance.tool_version = "0.1.0";
    provenance.parameters = {{"k", 1}};
    provenance.notes = {{"prototype_rule", "by hand"}};
    graph.utterances = {{0, 3}};
    graph.frame_count = 3;
    graph.states = {{0, VisemeClass::kSilence, {0, 1}}, {0, VisemeClass::kBilabial, {1, 2}}};
    graph.phones = {Phone::SIL, Phone::M};
    const std::vector<VoiceFeaturePoint> points = {{"8.1", 0, {0.0, -0.02, 0.1}}};
    const std::vector<VoiceRigidMarker> rigid = {{"H.temple_l", 0, {0.07, 0.03, 0.0}, {0.07, 0.03, 0.01}},
                                                 {"H.temple_r", 1, {-0.07, 0.03, 0.0}, {-0.07, 0.03, 0.01}},
                                                 {"H.nose_bridge", 2, {0.0, 0.04, 0.09}, {0.0, 0.04, 0.1}}};
    feature_points = voice_feature_points_json(points, rigid);
  }

  // Puts 8.1 (vertex 0) and the three rigid markers (vertices 0, 1, 2) on `face_m` (3 x N,
  // metres): the voice's neutral face is then `face_m` at those vertices.
  void set_neutral_face(const Eigen::Matrix3Xf& face_m) {
    const auto at = [&](int v) { return Eigen::Vector3d(face_m.col(v).cast<double>()); };
    const std::vector<VoiceFeaturePoint> points = {{"8.1", 0, at(0)}};
    const std::vector<VoiceRigidMarker> rigid = {{"H.temple_l", 0, at(0), {0.07, 0.03, 0.01}},
                                                 {"H.temple_r", 1, at(1), {-0.07, 0.03, 0.01}},
                                                 {"H.nose_bridge", 2, at(2), {0.0, 0.04, 0.1}}};
    feature_points = voice_feature_points_json(points, rigid);
  }

  // Inner lips 2.2 (vertex 0) and 2.3 (vertex 1) as the feature points, and a lip-contact term
  // whose shape moves vertex 0 down and vertex 1 up by 4 mm a unit.
  void set_inner_lips_with_contact() {
    const std::vector<VoiceFeaturePoint> points = {{"2.2", 0, {0.0, -0.02, 0.1}}, {"2.3", 1, {0.0, -0.03, 0.1}}};
    const std::vector<VoiceRigidMarker> rigid = {{"H.temple_l", 0, {0.07, 0.03, 0.0}, {0.07, 0.03, 0.01}},
                                                 {"H.temple_r", 1, {-0.07, 0.03, 0.0}, {-0.07, 0.03, 0.01}},
                                                 {"H.nose_bridge", 2, {0.0, 0.04, 0.09}, {0.0, 0.04, 0.1}}};
    feature_points = voice_feature_points_json(points, rigid);
    source_points = 2;
    lip_contact_shape = RowMajorMatrixXf::Zero(1, 3 * vertices);
    (*lip_contact_shape)(0, 1) = -0.004f, (*lip_contact_shape)(0, 4) = 0.004f;
    lip_contact = RowMajorMatrixXd::Zero(1, 5 + centres);
    *lip_contact << 0.006, -0.008, 0.0005, 0.0, 0.002, RowMajorMatrixXd::Zero(1, centres);
  }

  // Written to the temporary directory as `name` and opened.
  Voice open(const std::string& name) const {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / name;
    write_file_atomically(file, bytes());
    return Voice::open(file);
  }

  std::string bytes() const {
    VoiceFileWriter w;
    auto add = [&](SectionId id, auto matrix) {
      if (!(id == skip)) w.add_matrix(id, matrix);
    };
    if (!(voice_section::kProvenance == skip)) w.add_provenance(provenance);
    const Eigen::Index d = 3 * vertices;
    const RowMajorMatrixXf ramp = RowMajorMatrixXf(Eigen::RowVectorXf::LinSpaced(d, 0.f, static_cast<float>(d - 1)));
    RowMajorMatrixXf pc = RowMajorMatrixXf::Zero(components, d), rbf = RowMajorMatrixXf::Zero(centres, d);
    RowMajorMatrixXd centre = RowMajorMatrixXd::Zero(centres, 3 * source_points);
    for (Eigen::Index r = 0; r < components; ++r) pc(r, r + 1) = 1.f;
    for (Eigen::Index j = 0; j < centres; ++j) {
      rbf(j, 1) = j % 2 == 0 ? 1.f : -1.f;
      if (j > 0) centre(j, 1) = -0.01 * static_cast<double>(j);  // (not -0.0: the fixtures are byte-exact)
    }
    add(voice_section::kPcaMean, ramp);
    add(voice_section::kPcaComponents, pca_components ? *pca_components : pc);
    add(voice_section::kPcaVariances,
        pca_variances ? *pca_variances : RowMajorMatrixXf(RowMajorMatrixXf::Constant(1, components, 0.25f)));
    add(voice_section::kFrameCoefficients, coefficients);
    add(voice_section::kRbfCentres, centre);
    add(voice_section::kRbfWeights, rbf);
    add(voice_section::kRbfOffset, ramp);
    add(voice_section::kRbfScalars, RowMajorMatrixXd{{1e-4, 1e-6}});
    if (!(voice_section::kPhoneGraph == skip)) {
      const auto g = encode_voice_graph(graph);
      w.add(voice_section::kPhoneGraph, ElementType::kBytes, 1, g.size(), g);
    }
    if (!(voice_section::kFeaturePoints == skip))
      w.add(voice_section::kFeaturePoints, ElementType::kJson, 1, feature_points.size(), 
            std::as_bytes(std::span(feature_points)));
    if (face_maps) w.add_matrix(voice_section::kFaceMaps, *face_maps);
    if (lip_contact_shape) w.add_matrix(voice_section::kLipContactShape, *lip_contact_shape);
    if (lip_contact) w.add_matrix(voice_section::kLipContact, *lip_contact);
    return w.bytes();
  }
};

}  // namespace fapcast::test
