// The voice build's target prototypes against the talker's articulation tables.
#include "fapcast/builder/voice_prototypes.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "fapcast/talker/articulation.hpp"
#include "fapcast/face/face_model.hpp"

namespace fapcast {
namespace {

const std::filesystem::path kSpecDir = std::filesystem::path(FAPCAST_SOURCE_DIR) / "spec";

// The "articulation" rows are what the talker's own channel map gives for the class's phones'
// mean targets; detail rows add to it and say why. Every class has a recipe, every shape exists.
TEST(TargetPrototypes, RecipesFollowTheArticulationTables) {
  const FaceModel& face = ict_face_model();
  const ShapeMapper mapper(face);
  const auto spec = read_prototype_spec(kSpecDir / "prototypes.tsv");
  std::map<std::string, std::map<std::string, const PrototypeSpecRow*>> by_class;
  for (const auto& row : spec) {
    EXPECT_TRUE(by_class[row.viseme_class].emplace(row.shape, &row).second) << row.viseme_class << " " << row.shape;
    EXPECT_NO_THROW((void)face.expression_index(row.shape)) << row.shape;
    EXPECT_GT(row.weight, 0.0f);
    EXPECT_LE(row.weight, 1.0f);
    EXPECT_TRUE(row.basis == "articulation" || row.basis == "articulation+detail" || row.basis == "detail") << row.basis;
    EXPECT_EQ(row.basis == "articulation", row.why == "-") << row.viseme_class << " " << row.shape;
  }
  EXPECT_EQ(by_class.size(), kVisemeClassCount);
  for (std::size_t v = 0; v < kVisemeClassCount; ++v) {
    const auto cls = static_cast<VisemeClass>(v);
    const std::string name(viseme_class_name(cls));
    SCOPED_TRACE(name);
    std::array<float, kChannelCount> mean{};
    int phones = 0;
    for (const auto& row : kVisemeTable) {
      if (row.search_class != cls) continue;
      const auto& a = phone_articulation(row.phone == Phone::SIL ? "sil" : arpabet(row.phone));
      for (std::size_t c = 0; c < kChannelCount; ++c) mean[c] += a.target[c];
      ++phones;
    }
    for (auto& x : mean) x /= static_cast<float>(phones);
    const std::vector<float> weights = mapper(mean);
    const auto& recipe = by_class[name];
    for (std::size_t s = 0; s < weights.size(); ++s) {
      const auto it = recipe.find(face.expression_names[s]);
      const float articulation = weights[s] < 0.0005f ? 0.0f : weights[s];
      if (it == recipe.end()) {
        EXPECT_EQ(articulation, 0.0f) << face.expression_names[s] << " missing from the recipe";
      } else if (it->second->basis == "articulation") {
        EXPECT_NEAR(it->second->weight, articulation, 0.0006) << face.expression_names[s];
      } else if (it->second->basis == "articulation+detail") {
        EXPECT_GT(it->second->weight, articulation + 0.01) << face.expression_names[s];
        EXPECT_GT(articulation, 0.0f) << face.expression_names[s];
      } else {
        EXPECT_EQ(articulation, 0.0f) << face.expression_names[s] << " is a detail but articulation drives it";
      }
    }
  }
}

}  // namespace
}  // namespace fapcast
