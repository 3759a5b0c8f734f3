#include "fapcast/face/marker_map.hpp"

#include <algorithm>
#include <stdexcept>

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/tsv_table.hpp"

namespace fapcast {
namespace {

using enum MarkerRole;

// One row per marker; spec/markers.tsv says how each vertex was chosen.
constexpr std::array kMarkerSites{
    MarkerSite{"2.2", 5533, inner_lip},   MarkerSite{"2.3", 5517, inner_lip},
    MarkerSite{"2.4", 6207, inner_lip},   MarkerSite{"2.5", 5702, inner_lip},
    MarkerSite{"2.6", 6216, inner_lip},   MarkerSite{"2.7", 5711, inner_lip},
    MarkerSite{"2.8", 6470, inner_lip},   MarkerSite{"2.9", 5966, inner_lip},
    MarkerSite{"8.1", 0, outer_lip},      MarkerSite{"8.2", 5518, outer_lip},
    MarkerSite{"8.3", 6213, outer_lip},   MarkerSite{"8.4", 5708, outer_lip},
    MarkerSite{"8.5", 6200, outer_lip},   MarkerSite{"8.6", 5695, outer_lip},
    MarkerSite{"8.7", 6461, outer_lip},   MarkerSite{"8.8", 5957, outer_lip},
    MarkerSite{"2.1", 966, jaw},          MarkerSite{"2.10", 968, jaw},
    MarkerSite{"2.11", 4390, jaw},        MarkerSite{"2.12", 2199, jaw},
    MarkerSite{"2.13", 3924, jaw},        MarkerSite{"2.14", 1719, jaw},
    MarkerSite{"5.1", 2440, cheek},       MarkerSite{"5.2", 199, cheek},
    MarkerSite{"5.3", 3380, cheek},       MarkerSite{"5.4", 1161, cheek},
    MarkerSite{"9.1", 5233, nose},        MarkerSite{"9.2", 4768, nose},
    MarkerSite{"9.3", 4857, nose},        MarkerSite{"9.15", 1147, nose},
    MarkerSite{"3.1", 4161, fapu},        MarkerSite{"3.3", 3768, fapu},
    MarkerSite{"3.5", 25187, fapu},       MarkerSite{"3.6", 25339, fapu},
    MarkerSite{"H.forehead", 10481, rigid},   MarkerSite{"H.forehead_l", 9963, rigid},
    MarkerSite{"H.forehead_r", 9941, rigid},  MarkerSite{"H.temple_l", 10208, rigid},
    MarkerSite{"H.temple_r", 10228, rigid},
};

}  // namespace

std::string_view marker_role_name(MarkerRole role) {
  switch (role) {
    case inner_lip: return "inner_lip";
    case outer_lip: return "outer_lip";
    case jaw: return "jaw";
    case cheek: return "cheek";
    case nose: return "nose";
    case fapu: return "fapu";
    case rigid: return "rigid";
  }
  return "?";
}

std::span<const MarkerSite> marker_sites() { return kMarkerSites; }

std::size_t marker_row(std::string_view label) {
  for (std::size_t i = 0; i < kMarkerSites.size(); ++i)
    if (kMarkerSites[i].label == label) return i;
  throw std::out_of_range("no marker labelled '" + std::string(label) + "'");
}

std::vector<std::size_t> rigid_marker_rows() {
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < kMarkerSites.size(); ++i)
    if (kMarkerSites[i].role == rigid) rows.push_back(i);
  return rows;
}

std::vector<std::int32_t> marker_vertices() {
  std::vector<std::int32_t> v;
  for (const auto& site : kMarkerSites) v.push_back(site.vertex);
  return v;
}

Positions marker_positions(const Positions& mesh, std::span<const std::int32_t> vertices) {
  Positions out(3, static_cast<Eigen::Index>(vertices.size()));
  for (std::size_t m = 0; m < vertices.size(); ++m) {
    if (vertices[m] < 0 || vertices[m] >= mesh.cols())
      throw std::out_of_range("marker vertex " + std::to_string(vertices[m]) + " outside a " +
                              std::to_string(mesh.cols()) + "-vertex mesh");
    out.col(static_cast<Eigen::Index>(m)) = mesh.col(vertices[m]);
  }
  return out;
}

std::vector<MarkerSpecRow> read_marker_spec(const std::filesystem::path& file) {
  std::vector<MarkerSpecRow> out;
  for (const auto& row : read_tsv(file, 4)) {
    out.push_back({row.fields[0],
                   static_cast<std::int32_t>(tsv_integer(file, row, 1, 0, 2'000'000)),
                   row.fields[2], row.fields[3]});
  }
  return out;
}

MarkerBlender::MarkerBlender(const FaceModel& face, std::span<const std::int32_t> vertices)
    : neutral_(marker_positions(face.neutral_cm, vertices)),
      offsets_(Eigen::MatrixXf::Zero(3 * static_cast<Eigen::Index>(vertices.size()),
                                     static_cast<Eigen::Index>(face.expressions.size()))) {
  for (std::size_t k = 0; k < face.expressions.size(); ++k) {
    const auto& delta = face.expressions[k];
    for (std::size_t m = 0; m < vertices.size(); ++m) {
      const auto it = std::lower_bound(delta.vertices.begin(), delta.vertices.end(), vertices[m]);
      if (it == delta.vertices.end() || *it != vertices[m]) continue;
      offsets_.block<3, 1>(3 * static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(k)) =
          delta.offsets_cm.col(it - delta.vertices.begin());
    }
  }
}

Positions MarkerBlender::operator()(std::span<const float> expression_weights) const {
  if (static_cast<Eigen::Index>(expression_weights.size()) != offsets_.cols())
    throw std::invalid_argument("MarkerBlender: " + std::to_string(expression_weights.size()) +
                                " weights for " + std::to_string(offsets_.cols()) + " shapes");
  const Eigen::Map<const Eigen::VectorXf> w(expression_weights.data(), offsets_.cols());
  Eigen::VectorXf flat = offsets_ * w;
  return neutral_ + Eigen::Map<const Positions>(flat.data(), 3, neutral_.cols());
}

}  // namespace fapcast
