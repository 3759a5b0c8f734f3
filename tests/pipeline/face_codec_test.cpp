// Where the face meets the codec: the six expressions are FAP 2's, and the codec measures every
// FAPU on the talker's face from the marker table's points.
#include <gtest/gtest.h>

#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/codec/fapu_values.hpp"
#include "fapcast/codec/feature_point.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/facial_expression.hpp"
#include "fapcast/face/marker_map.hpp"

#include <string_view>
#include <vector>

namespace fapcast {
namespace {

// Numbering and names as in FAP 2 (codec's ExpressionField: 1 joy ... 6 surprise).
TEST(FacialExpression, NamesAndNumbersAreFap2s) {
  const std::vector<std::string_view> names{"joy", "sadness", "anger", "fear", "disgust", "surprise"};
  ASSERT_EQ(all_expressions().size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    const Expression e = all_expressions()[i];
    EXPECT_EQ(static_cast<int>(e), static_cast<int>(i) + 1);
    EXPECT_EQ(expression_name(e), names[i]);
    EXPECT_EQ(expression_from_name(names[i]), e);
    ExpressionField field;
    field.select1 = static_cast<std::uint8_t>(e);  // fits FAP 2's 0..6 field
    EXPECT_LE(field.select1, 6);
  }
  EXPECT_THROW(expression_from_name("happy"), std::invalid_argument);
}

// The codec can measure every FAPU on the talker's face from these points.
TEST(MarkerMap, FapuMeasurableOnTheFace) {
  const auto& face = ict_face_model();
  FeaturePointPositions fp;
  for (const char* label : {"9.15", "2.2", "8.3", "8.4", "3.5", "3.6", "3.1", "3.3"}) {
    const auto point = parse_feature_point(label);
    ASSERT_TRUE(point.has_value()) << label;
    fp[*point] = face.neutral_cm.col(marker_sites()[marker_row(label)].vertex).cast<double>();
  }
  const auto f = measure_fapu(fp);
  EXPECT_NEAR(f.mns * 1024, 2.1, 0.3);  // cm: nose bottom to upper inner lip
  EXPECT_NEAR(f.mw * 1024, 5.06, 0.3);  // cm: mouth width
  EXPECT_GT(f.ens, 0);
  EXPECT_NEAR(f.es * 1024, 6.5, 0.5);   // cm: pupils
  EXPECT_GT(f.irisd, 0);
}

}  // namespace
}  // namespace fapcast
