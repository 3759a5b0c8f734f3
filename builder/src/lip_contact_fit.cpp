#include "fapcast/builder/lip_contact_fit.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "fapcast/builder/voice_corpus.hpp"
#include "fapcast/face/marker_map.hpp"

namespace fapcast {
namespace {

// The rows of 2.2 and 2.3 in a source vector (source_marker_rows() order) and of their vertices in
// the target vector.
struct LipContactRows {
  Eigen::Index source_upper, source_lower, target_upper, target_lower;
};

LipContactRows lip_contact_rows() {
  const auto sites = marker_sites();
  const auto rows = source_marker_rows();
  LipContactRows out{-1, -1, -1, -1};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const MarkerSite& s = sites[rows[i]];
    if (s.label == "2.2") out.source_upper = 3 * static_cast<Eigen::Index>(i), out.target_upper = 3 * Eigen::Index{s.vertex};
    if (s.label == "2.3") out.source_lower = 3 * static_cast<Eigen::Index>(i), out.target_lower = 3 * Eigen::Index{s.vertex};
  }
  if (out.source_upper < 0 || out.source_lower < 0)
    throw std::logic_error("lip_contact_rows: spec/markers.tsv has no 2.2 or 2.3");
  return out;
}

}  // namespace

std::optional<LipContact> fit_lip_contact(const FaceModel& face, const RbfMap& map, const Eigen::MatrixXd& source,
                                          std::span<const PhoneState> states,
                                          const Eigen::Ref<const Eigen::VectorXd>& bilabial_target) {
  const LipContactRows rows = lip_contact_rows();
  LipContact c;
  c.source_upper = rows.source_upper, c.source_lower = rows.source_lower;
  c.reach_m = kLipContactReachM;
  std::vector<double> closest;
  for (const PhoneState& s : states) {
    if (s.viseme != VisemeClass::kBilabial || s.frames.count == 0) continue;
    double least = 1e300;
    for (std::uint32_t f = s.frames.first; f < s.frames.first + s.frames.count; ++f)
      least = std::min(least, c.source_gap_m(source.col(f)));
    closest.push_back(least);
  }
  if (closest.empty()) return std::nullopt;
  std::nth_element(closest.begin(), closest.begin() + static_cast<std::ptrdiff_t>(closest.size() / 2), closest.end());
  c.source_contact_m = closest[closest.size() / 2];
  const Eigen::Index uy = rows.target_upper + 1, ly = rows.target_lower + 1;
  c.target_contact_m = bilabial_target(uy) - bilabial_target(ly);
  c.gap_weights = map.weights().col(uy) - map.weights().col(ly);
  c.gap_offset_m = map.offset()(uy) - map.offset()(ly);
  const SparseDelta& close = face.expressions[face.expression_index("mouthClose")];
  c.shape = Eigen::VectorXd::Zero(3 * Eigen::Index{face.vertex_count()});
  for (std::size_t i = 0; i < close.vertices.size(); ++i)
    c.shape.segment<3>(3 * Eigen::Index{close.vertices[i]}) = close.offsets_cm.col(static_cast<Eigen::Index>(i)).cast<double>() / 100.0;
  c.shape_gap_m = c.shape(uy) - c.shape(ly);
  if (!(c.shape_gap_m < 0)) throw std::logic_error("fit_lip_contact: the face's mouthClose does not close its inner lips");
  return c;
}

}  // namespace fapcast
