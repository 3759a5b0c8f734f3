#include "fapcast/face/marker_map.hpp"

#include <gtest/gtest.h>

#include <set>


namespace fapcast {
namespace {

const std::filesystem::path kSpec = std::filesystem::path(FAPCAST_SOURCE_DIR) / "spec" / "markers.tsv";

TEST(MarkerMap, AgreesWithSpec) {
  const auto spec = read_marker_spec(kSpec);
  const auto table = marker_sites();
  ASSERT_EQ(spec.size(), table.size());
  for (std::size_t i = 0; i < spec.size(); ++i) {
    SCOPED_TRACE(spec[i].label);
    EXPECT_EQ(spec[i].label, table[i].label);
    EXPECT_EQ(spec[i].vertex, table[i].vertex);
    EXPECT_EQ(spec[i].role, marker_role_name(table[i].role));
    EXPECT_FALSE(spec[i].how_chosen.empty());
  }
}

TEST(MarkerMap, CoversTheLowerFaceFapuPointsAndFourRigidMarkers) {
  std::set<std::string_view> labels;
  for (const auto& s : marker_sites()) EXPECT_TRUE(labels.insert(s.label).second) << s.label;
  for (const char* fp : {"2.1", "2.2", "2.3", "2.4", "2.5", "2.6", "2.7", "2.8", "2.9", "2.10",
                         "2.11", "2.12", "2.13", "2.14", "8.1", "8.2", "8.3", "8.4", "8.5", "8.6",
                         "8.7", "8.8", "5.1", "5.2", "5.3", "5.4", "9.1", "9.2", "9.3", "9.15",
                         "3.1", "3.3", "3.5", "3.6"})
    EXPECT_TRUE(labels.count(fp)) << fp;
  EXPECT_GE(rigid_marker_rows().size(), 4u);
}

TEST(MarkerMap, VerticesAreOnTheMeshAndSidesAreRight) {
  const auto& face = ict_face_model();
  for (const auto& s : marker_sites()) {
    ASSERT_GE(s.vertex, 0);
    ASSERT_LT(s.vertex, face.vertex_count());
  }
  const auto x = [&](std::string_view label) { return face.neutral_cm(0, marker_sites()[marker_row(label)].vertex); };
  const auto y = [&](std::string_view label) { return face.neutral_cm(1, marker_sites()[marker_row(label)].vertex); };
  // The face's own left is +x; mirror pairs are symmetric on ICT's symmetric generic face.
  for (const auto& [left, right] : {std::pair{"2.4", "2.5"}, {"8.3", "8.4"}, {"2.11", "2.12"},
                                     {"2.13", "2.14"}, {"5.1", "5.2"}, {"5.3", "5.4"}, {"9.1", "9.2"},
                                     {"3.5", "3.6"}, {"8.5", "8.6"}, {"8.7", "8.8"}, {"2.6", "2.7"}}) {
    EXPECT_GT(x(left), 0.5f) << left;
    EXPECT_NEAR(x(left), -x(right), 1e-3f) << left;
  }
  // Vertical order on the midline: nose bottom > outer upper lip > inner lips > outer lower > chin.
  EXPECT_GT(y("9.15"), y("8.1"));
  EXPECT_GT(y("8.1"), y("2.2"));
  EXPECT_GE(y("2.2"), y("2.3"));
  EXPECT_GT(y("2.3"), y("8.2"));
  EXPECT_GT(y("8.2"), y("2.10"));
  EXPECT_GT(y("2.10"), y("2.1"));
  EXPECT_GT(y("3.1"), y("3.3"));
}

// A rigid marker is useful for pose removal only if no expression moves it.
TEST(MarkerMap, RigidMarkersAreMovedByNoExpressionShape) {
  const auto& face = ict_face_model();
  for (const auto row : rigid_marker_rows()) {
    const auto v = marker_sites()[row].vertex;
    for (std::size_t k = 0; k < face.expressions.size(); ++k) {
      const auto& d = face.expressions[k].vertices;
      EXPECT_FALSE(std::binary_search(d.begin(), d.end(), v))
          << marker_sites()[row].label << " moved by " << face.expression_names[k];
    }
  }
  // ... and speech moves every lip marker.
  const auto& jaw = face.expressions[face.expression_index("jawOpen")].vertices;
  for (const auto& s : marker_sites()) {
    if (s.role == MarkerRole::inner_lip || s.role == MarkerRole::outer_lip || s.role == MarkerRole::jaw) {
      EXPECT_TRUE(std::binary_search(jaw.begin(), jaw.end(), s.vertex)) << s.label;
    }
  }
}

// The marker-only blend agrees with blending the whole mesh and picking the vertices.
TEST(MarkerMap, MarkerBlenderEqualsFullBlend) {
  const auto& face = ict_face_model();
  const auto vertices = marker_vertices();
  const MarkerBlender blender(face, vertices);
  std::vector<float> w(face.expressions.size());
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = static_cast<float>((i * 7) % 5) / 5.0f;
  const Positions full = marker_positions(blend(face.neutral_cm, face.expressions, w), vertices);
  EXPECT_LT((blender(w) - full).cwiseAbs().maxCoeff(), 1e-5f);
}

}  // namespace
}  // namespace fapcast
