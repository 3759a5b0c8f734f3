#pragma once
// Where the reference talker's capture markers sit on the ICT-FaceKit mesh (spec/markers.tsv).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/face/face_model.hpp"

namespace fapcast {

enum class MarkerRole : std::uint8_t { inner_lip, outer_lip, jaw, cheek, nose, fapu, rigid };

// "inner_lip", "outer_lip", "jaw", "cheek", "nose", "fapu", "rigid".
std::string_view marker_role_name(MarkerRole role);

struct MarkerSite {
  std::string_view label;  // MPEG-4 feature point ("2.2") or rigid head marker ("H.temple_l")
  std::int32_t vertex;     // 0-based ICT generic-mesh vertex
  MarkerRole role;
};

// The marker table, in spec/markers.tsv order: 34 feature points, then 5 rigid head markers.
std::span<const MarkerSite> marker_sites();

// Position (row) of a marker label in marker_sites(); throws std::out_of_range naming it.
std::size_t marker_row(std::string_view label);

// Rows of the rigid head markers (moved by no ICT expression shape).
std::vector<std::size_t> rigid_marker_rows();

// Vertex indices of all markers, in table order.
std::vector<std::int32_t> marker_vertices();

// Picks the marker vertices out of a mesh: 3 x M, cm.
Positions marker_positions(const Positions& mesh, std::span<const std::int32_t> vertices);

// One row of spec/markers.tsv as read from disk.
struct MarkerSpecRow {
  std::string label;
  std::int32_t vertex;
  std::string role;
  std::string how_chosen;
};

// Reads spec/markers.tsv (4 tab-separated columns); throws InputError.
std::vector<MarkerSpecRow> read_marker_spec(const std::filesystem::path& file);

// Blends only the marker vertices: precomputes each shape's offsets at the markers, so one frame
// costs M x K multiply-adds instead of touching the whole mesh.
class MarkerBlender {
 public:
  MarkerBlender(const FaceModel& face, std::span<const std::int32_t> vertices);
  // Marker positions (3 x M, cm) for expression weights (one per face expression shape).
  Positions operator()(std::span<const float> expression_weights) const;
  std::size_t marker_count() const { return static_cast<std::size_t>(neutral_.cols()); }

 private:
  Positions neutral_;           // 3 x M
  Eigen::MatrixXf offsets_;     // 3M x K
};

}  // namespace fapcast
