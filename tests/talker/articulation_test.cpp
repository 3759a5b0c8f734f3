#include "fapcast/talker/articulation.hpp"

#include <gtest/gtest.h>

#include <set>

namespace fapcast {
namespace {

const std::filesystem::path kSpecDir = std::filesystem::path(FAPCAST_SOURCE_DIR) / "spec";

TEST(Articulation, TableAgreesWithSpec) {
  const auto spec = read_articulation_spec(kSpecDir / "articulation.tsv");
  const auto table = articulation_table();
  ASSERT_EQ(spec.size(), table.size());
  for (std::size_t i = 0; i < spec.size(); ++i) {
    SCOPED_TRACE(spec[i].phone + " " + spec[i].channel);
    EXPECT_EQ(spec[i].phone, table[i].phone);
    EXPECT_EQ(spec[i].channel, channel_name(table[i].channel));
    EXPECT_FLOAT_EQ(spec[i].target, table[i].target);
    EXPECT_FLOAT_EQ(spec[i].alpha, table[i].dominance.alpha);
    EXPECT_FLOAT_EQ(spec[i].theta_before, table[i].dominance.theta_before_per_s);
    EXPECT_FLOAT_EQ(spec[i].theta_after, table[i].dominance.theta_after_per_s);
    EXPECT_FLOAT_EQ(spec[i].c, table[i].dominance.c);
  }
}

TEST(Articulation, ShapeMapAgreesWithSpec) {
  const auto spec = read_channel_shape_spec(kSpecDir / "articulation_shapes.tsv");
  const auto table = channel_shape_table();
  ASSERT_EQ(spec.size(), table.size());
  for (std::size_t i = 0; i < spec.size(); ++i) {
    SCOPED_TRACE(spec[i].channel + " " + spec[i].shape);
    EXPECT_EQ(spec[i].channel, channel_name(table[i].channel));
    EXPECT_EQ(spec[i].shape, table[i].shape);
    EXPECT_FLOAT_EQ(spec[i].weight, table[i].weight);
    EXPECT_EQ(spec[i].scale_by, table[i].scale_by ? channel_name(*table[i].scale_by) : "-");
    EXPECT_EQ(spec[i].gated, table[i].gated);
  }
}

// 39 ARPAbet phones + AX + sil, each with every channel exactly once, values in range.
TEST(Articulation, EveryPhoneHasEveryChannel) {
  const auto phones = articulation_phones();
  EXPECT_EQ(phones.size(), 41u);
  const std::set<std::string_view> expected{
      "sil", "AA", "AE", "AH", "AO", "AW", "AX", "AY", "B", "CH", "D", "DH", "EH", "ER", "EY",
      "F",   "G",  "HH", "IH", "IY", "JH", "K",  "L", "M",  "N", "NG", "OW", "OY", "P",
      "R",   "S",  "SH", "T",  "TH", "UH", "UW", "V", "W",  "Y", "Z",  "ZH"};
  EXPECT_EQ(std::set<std::string_view>(phones.begin(), phones.end()), expected);
  std::set<std::pair<std::string_view, Channel>> seen;
  for (const auto& row : articulation_table()) {
    EXPECT_TRUE(seen.insert({row.phone, row.channel}).second) << row.phone;
    EXPECT_GE(row.target, 0.0f);
    EXPECT_LE(row.target, 1.0f);
    EXPECT_GT(row.dominance.alpha, 0.0f);
    EXPECT_GT(row.dominance.theta_before_per_s, 0.0f);
    EXPECT_GT(row.dominance.theta_after_per_s, 0.0f);
    EXPECT_GT(row.dominance.c, 0.0f);
  }
  EXPECT_EQ(seen.size(), 41 * kChannelCount);
}

TEST(Articulation, LooksUpSymbolsWithStressAndRefusesUnknown) {
  EXPECT_EQ(&phone_articulation("AH0"), &phone_articulation("AH"));
  EXPECT_EQ(&phone_articulation("UW1"), &phone_articulation("UW"));
  EXPECT_EQ(&phone_articulation(""), &phone_articulation("sil"));
  try {
    (void)phone_articulation("QX");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'QX'"), std::string::npos);
  }
  for (std::size_t c = 0; c < kChannelCount; ++c)
    EXPECT_EQ(channel_from_name(channel_name(static_cast<Channel>(c))), static_cast<Channel>(c));
  EXPECT_THROW((void)channel_from_name("nose"), std::invalid_argument);
}

// Bilabials and labiodentals override: their peak dominance is at least 50 times any other
// phone's on that channel, so at their centre they win against any neighbours.
TEST(Articulation, ContactsHaveOverridingDominance) {
  const auto ch = [](Channel c) { return static_cast<std::size_t>(c); };
  float others_closure = 0, others_labio = 0;
  for (const auto p : articulation_phones()) {
    const auto& a = phone_articulation(p);
    if (p != "P" && p != "B" && p != "M")
      others_closure = std::max(others_closure, a.dominance[ch(Channel::closure)].alpha);
    if (p != "F" && p != "V")
      others_labio = std::max(others_labio, a.dominance[ch(Channel::labiodental)].alpha);
  }
  for (const char* p : {"P", "B", "M"}) {
    EXPECT_EQ(phone_articulation(p).target[ch(Channel::closure)], 1.0f);
    EXPECT_GT(phone_articulation(p).dominance[ch(Channel::closure)].alpha, 50 * others_closure);
  }
  for (const char* p : {"F", "V"})
    EXPECT_GT(phone_articulation(p).dominance[ch(Channel::labiodental)].alpha, 50 * others_labio);
}

// The calibration's class rule (spec/talker.md): the lips' own opening is one target for every
// unrounded vowel, the height differences are the jaw's; the jaw still orders them by height.
TEST(Articulation, UnroundedVowelsShareOneLipOpeningAndDifferInJaw) {
  const auto ch = [](Channel c) { return static_cast<std::size_t>(c); };
  const float lips = phone_articulation("AH").target[ch(Channel::lip_opening)];
  for (const char* p : {"AA", "AE", "AY", "EH", "EY", "IH", "IY"}) {
    EXPECT_EQ(phone_articulation(p).target[ch(Channel::lip_opening)], lips) << p;
    EXPECT_EQ(phone_articulation(p).target[ch(Channel::rounding)], 0.0f) << p;
  }
  EXPECT_GT(phone_articulation("AA").target[ch(Channel::jaw)], phone_articulation("EH").target[ch(Channel::jaw)]);
  EXPECT_GT(phone_articulation("EH").target[ch(Channel::jaw)], phone_articulation("IY").target[ch(Channel::jaw)]);
}

TEST(Articulation, DominanceIsAsymmetricAndPeaksAtTheCentre) {
  const Dominance d{2.0f, 5.0f, 20.0f, 1.0f};
  EXPECT_DOUBLE_EQ(d.at(0.0), 2.0);
  EXPECT_NEAR(d.at(-0.1), 2.0 * std::exp(-0.5), 1e-12);
  EXPECT_NEAR(d.at(0.1), 2.0 * std::exp(-2.0), 1e-12);
  EXPECT_GT(d.at(-0.1), d.at(0.1));
}

TEST(Articulation, ShapeMapperUsesRealIctShapesAndStaysInRange) {
  const auto& face = ict_face_model();
  const ShapeMapper mapper(face);
  EXPECT_EQ(mapper.shape_count(), face.expressions.size());
  std::array<float, kChannelCount> all_on{};
  all_on.fill(1.0f);
  for (const auto& values : {all_on, std::array<float, kChannelCount>{}}) {
    for (const float w : mapper(values)) {
      EXPECT_GE(w, 0.0f);
      EXPECT_LE(w, 1.0f);
    }
  }
  // Closure with an open jaw drives mouthClose in proportion to the jaw and gates lip opening.
  std::array<float, kChannelCount> v{};
  v[static_cast<std::size_t>(Channel::jaw)] = 0.5f;
  v[static_cast<std::size_t>(Channel::lip_opening)] = 0.8f;
  v[static_cast<std::size_t>(Channel::closure)] = 1.0f;
  const auto w = mapper(v);
  EXPECT_NEAR(w[face.expression_index("mouthClose")], 0.83f * 0.5f, 1e-6f);
  EXPECT_EQ(w[face.expression_index("mouthLowerDown_L")], 0.0f);
  EXPECT_NEAR(jaw_opening_angle_rad(0.5f), 0.175, 1e-9);
}

}  // namespace
}  // namespace fapcast
