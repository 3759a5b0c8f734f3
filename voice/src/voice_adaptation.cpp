#include "fapcast/voice/voice_adaptation.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "fapcast/face/face_adaptation.hpp"

namespace fapcast {
namespace {

namespace vs = voice_section;
constexpr double kNeutralToleranceM = 1e-4;  // 0.1 mm: float rounding of cm -> m is ~1e-9 m

// Each row of `rows` (xyz interleaved per vertex) mapped by the adaptation, plus `base` when given.
RowMajorMatrixXf adapt_rows(const FaceAdaptation& a, const Eigen::Ref<const RowMajorMatrixXf>& rows,
                            const Positions* generic, const Positions* specific) {
  const Eigen::Index n = a.vertex_count();
  RowMajorMatrixXf out(rows.rows(), rows.cols());
  for (Eigen::Index r = 0; r < rows.rows(); ++r) {
    const RowMajorMatrixXf row = rows.row(r);  // contiguous
    Positions d = Eigen::Map<const Positions>(row.data(), 3, n);
    if (generic) d -= *generic;
    Positions y = a.adapt(d);
    if (specific) y += *specific;
    Eigen::Map<Positions>(out.row(r).data(), 3, n) = y;
  }
  return out;
}

void check_generic(const Voice& voice, const Positions& generic_m) {
  for (const auto& p : voice.feature_points()) {
    const Eigen::Vector3d at = generic_m.col(p.vertex).cast<double>();
    if ((at - p.neutral_m).norm() > kNeutralToleranceM) {
      const Eigen::IOFormat xyz(Eigen::StreamPrecision, Eigen::DontAlignCols, ", ", ", ");
      std::ostringstream m;
      m << "generic-mismatch: feature point " << p.label << " (vertex " << p.vertex << ") is at ("
        << at.transpose().format(xyz) << ") m on the generic face but at (" << p.neutral_m.transpose().format(xyz)
        << ") m on the voice's neutral face: the generic mesh must be the voice's own face, in its unit";
      throw std::invalid_argument(m.str());
    }
  }
}

}  // namespace

AdaptedVoice adapt_voice(const Voice& voice, const Positions& generic_m, const Positions& specific_m,
                               const PolygonFaces& faces, const std::string& specific_name) {
  const Eigen::Index n = voice.dimension() / 3;
  if (generic_m.cols() != n || specific_m.cols() != n)
    throw std::invalid_argument("the voice's face has " + std::to_string(n) + " vertices, the generic mesh " +
                                std::to_string(generic_m.cols()) + " and the specific mesh " +
                                std::to_string(specific_m.cols()));
  check_generic(voice, generic_m);
  const FaceAdaptation a(generic_m, specific_m, faces);

  AdaptedVoice out;
  auto& s = out.summary;
  s.vertices = static_cast<std::size_t>(n);
  s.triangles = a.triangle_count();
  s.degenerate_triangles = a.degenerate_triangle_count();
  s.global_map_vertices = a.global_map_vertex_count();

  const VoiceFileView& view = voice.file();
  std::vector<VoiceFeaturePoint> points(voice.feature_points().begin(), voice.feature_points().end());
  for (auto& p : points) {
    const Eigen::Vector3d to = specific_m.col(p.vertex).cast<double>();
    s.max_feature_point_offset_m = std::max(s.max_feature_point_offset_m, (to - p.neutral_m).norm());
    p.neutral_m = to;
  }
  std::vector<VoiceRigidMarker> rigid(voice.rigid_markers().begin(), voice.rigid_markers().end());
  for (auto& r : rigid) r.neutral_m = specific_m.col(r.vertex).cast<double>();

  RowMajorMatrixXf maps(n, 9);
  const auto old_maps = voice.face_maps();
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Matrix3f m = a.vertex_map(static_cast<std::int32_t>(i));
    if (old_maps) m = m * Eigen::Map<const Eigen::Matrix<float, 3, 3, Eigen::RowMajor>>(old_maps->row(i).data());
    Eigen::Map<Eigen::Matrix<float, 3, 3, Eigen::RowMajor>>(maps.row(i).data()) = m;
  }

  VoiceProvenance provenance = voice.provenance();
  provenance.target_face += " re-targeted to " + specific_name;
  const auto note = provenance.notes.find("retarget");
  provenance.notes["retarget"] = (note == provenance.notes.end() ? std::string() : note->second + "; ") +
                                 "per-vertex affine maps to " + specific_name + " (spec/adaptation.md)";

  VoiceFileWriter writer;
  writer.add_provenance(provenance);
  writer.add_matrix(vs::kPcaMean, adapt_rows(a, voice.pca_mean(), &generic_m, &specific_m));
  writer.add_matrix(vs::kPcaComponents, adapt_rows(a, voice.pca_components(), nullptr, nullptr));
  writer.add_matrix(vs::kRbfWeights, adapt_rows(a, view.matrix_f32(vs::kRbfWeights), nullptr, nullptr));
  writer.add_matrix(vs::kRbfOffset, adapt_rows(a, view.matrix_f32(vs::kRbfOffset), &generic_m, &specific_m));
  const std::string fpnt = voice_feature_points_json(points, rigid);
  writer.add(vs::kFeaturePoints, ElementType::kJson, 1, fpnt.size(), std::as_bytes(std::span(fpnt)));
  writer.add_matrix(vs::kFaceMaps, maps);
  // The lip-contact shape is a displacement like the weights; its amounts (LCON) are the generic
  // face's and carry over as they are.
  if (view.find(vs::kLipContactShape) != nullptr)
    writer.add_matrix(vs::kLipContactShape, adapt_rows(a, view.matrix_f32(vs::kLipContactShape), nullptr, nullptr));
  for (const SectionInfo& section : view.sections()) {
    const SectionId id = section.id;
    if (id == vs::kProvenance || id == vs::kPcaMean || id == vs::kPcaComponents || id == vs::kRbfWeights ||
        id == vs::kRbfOffset || id == vs::kFeaturePoints || id == vs::kFaceMaps || id == vs::kLipContactShape)
      continue;
    writer.add(id, section.type, section.rows, section.cols, view.bytes(id));
  }
  out.bytes = writer.bytes();
  return out;
}

}  // namespace fapcast
