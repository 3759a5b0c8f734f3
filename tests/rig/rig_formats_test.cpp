// The rig formats against what their consumers expect: Live Link Face's header from a real export,
// OSC's byte layout, the VRM animation's and TalkingHead's JSON, and the ARKit table.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "fapcast/rig/arkit_shapes.hpp"
#include "fapcast/rig/live_link_csv.hpp"
#include "fapcast/rig/mouth_visemes.hpp"
#include "fapcast/rig/talkinghead_json.hpp"
#include "fapcast/rig/vmc_osc.hpp"
#include "fapcast/rig/vrm_animation.hpp"
#include "support/bad_inputs.hpp"

namespace fapcast {
namespace {

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST(LiveLinkCsv, HeaderIsTheAppsByteForByte) {
  const std::string real = test::slurp(std::string(FAPCAST_TEST_DATA) + "/rig/live-link-face-S07-001-head.csv");
  const std::string ours = live_link_csv(Eigen::MatrixXf::Zero(2, 52), {60, 1});
  EXPECT_EQ(first_line(ours), first_line(real));
  // rows: timecode, 61, then 61 values with 10 decimals, as the app's
  std::istringstream rows(real.substr(real.find('\n') + 1));
  std::string row;
  std::getline(rows, row);
  const auto commas = std::count(row.begin(), row.end(), ',');
  const std::string second = ours.substr(ours.find('\n') + 1);
  EXPECT_EQ(std::count(second.begin(), second.begin() + static_cast<long>(second.find('\n')), ','), commas);
  EXPECT_EQ(second.substr(0, 19), "00:00:00:00.000,61,");
}

TEST(LiveLinkCsv, TimecodesAndValues) {
  EXPECT_EQ(live_link_timecode(0, {60, 1}), "00:00:00:00.000");
  EXPECT_EQ(live_link_timecode(59, {60, 1}), "00:00:00:59.000");
  EXPECT_EQ(live_link_timecode(60, {60, 1}), "00:00:01:00.000");
  EXPECT_EQ(live_link_timecode(3600 * 60 + 61, {60, 1}), "01:00:01:01.000");
  EXPECT_EQ(live_link_timecode(1, {30, 1}), "00:00:00:02.000");
  EXPECT_EQ(live_link_timecode(1, {30000, 1001}), "00:00:00:02.002");
  EXPECT_EQ(live_link_timecode(24 * 3600 * 60, {60, 1}), "00:00:00:00.000");  // wraps at 24 h
  Eigen::MatrixXf w = Eigen::MatrixXf::Zero(1, 52);
  w(0, 17) = 0.123456789f;  // jawOpen
  const std::string csv = live_link_csv(w, {60, 1});
  const std::string row = csv.substr(csv.find('\n') + 1);
  std::vector<std::string> cells;
  std::stringstream ss(row.substr(0, row.find('\n')));
  for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
  ASSERT_EQ(cells.size(), 63u);
  EXPECT_EQ(cells[2 + 17], "0.1234567910");  // the float, 10 decimals
  EXPECT_FLOAT_EQ(std::stof(cells[2 + 17]), w(0, 17));
  EXPECT_THROW(live_link_csv(Eigen::MatrixXf::Zero(1, 51), {60, 1}), std::invalid_argument);
}

TEST(ArkitShapes, NamesAreArkitsAndEachIctShapeIsUsedOnce) {
  std::set<std::string_view> names, ict;
  for (const ArkitShape& s : kArkitShapes) {
    EXPECT_TRUE(names.insert(s.name).second) << s.name;
    for (std::string_view i : s.ict) {
      if (i.empty()) continue;
      EXPECT_TRUE(ict.insert(i).second) << i;
    }
  }
  EXPECT_EQ(ict.size(), 53u);  // ICT's 53 expression shapes, each in one ARKit shape
  EXPECT_EQ(kArkitShapes[17].name, "jawOpen");
  EXPECT_EQ(*arkit_index("tongueOut"), 51u);
  EXPECT_FALSE(arkit_index("JawOpen").has_value());
  EXPECT_EQ(live_link_name("mouthSmileLeft"), "MouthSmileLeft");
}

TEST(VmcOsc, BundleBytesFollowOscOnePointZero) {
  const std::vector<std::string> names{"A"};
  const std::vector<float> values{0.5f};
  const std::vector<std::uint8_t> b = vmc_blend_bundle(names, values, 1.0f);
  const auto text = [&](std::size_t at, const char* s) { return std::memcmp(b.data() + at, s, std::strlen(s) + 1) == 0; };
  ASSERT_TRUE(text(0, "#bundle"));
  EXPECT_EQ(b[15], 1);  // time tag 1: immediately
  // first element: size 16, "/VMC/Ext/OK\0" then ",i\0\0" then int 1 ... (sizes are multiples of 4)
  EXPECT_EQ(b[16 + 3], 20);
  EXPECT_TRUE(text(20, "/VMC/Ext/OK"));
  EXPECT_TRUE(text(32, ",i"));
  EXPECT_EQ(b[39], 1);
  std::size_t at = 16;
  std::vector<std::string> addresses;
  while (at < b.size()) {
    const std::uint32_t size = (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) | (std::uint32_t{b[at + 2]} << 8) | b[at + 3];
    ASSERT_EQ(size % 4, 0u);
    addresses.emplace_back(reinterpret_cast<const char*>(b.data() + at + 4));
    at += 4 + size;
  }
  EXPECT_EQ(at, b.size());
  EXPECT_EQ(addresses, (std::vector<std::string>{"/VMC/Ext/OK", "/VMC/Ext/T", "/VMC/Ext/Blend/Val", "/VMC/Ext/Blend/Apply"}));
  EXPECT_THROW(vmc_blend_bundle(std::vector<std::string>{""}, values, 0), std::invalid_argument);
}

nlohmann::json glb_json(const std::string& glb) {
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  std::uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  return nlohmann::json::parse(glb.substr(20, length));
}

TEST(VrmAnimation, ExpressionsAreNodesWhoseTranslationXIsTheWeight) {
  const std::vector<std::string> names{"aa", "ou", "jawOpen"};
  Eigen::MatrixXf w(4, 3);
  w << 0, 1, 0.5f, 0.25f, 0.5f, 0.75f, 1, 0, 0, 0.5f, 0.5f, 0.5f;
  const std::string glb = write_vrm_animation(names, w, {60, 1});
  const nlohmann::json j = glb_json(glb);
  const auto& ext = j["extensions"]["VRMC_vrm_animation"];
  EXPECT_EQ(ext["specVersion"], "1.0");
  EXPECT_EQ(ext["expressions"]["preset"]["aa"]["node"], 1);
  EXPECT_EQ(ext["expressions"]["custom"]["jawOpen"]["node"], 3);
  EXPECT_EQ(j["nodes"][0]["translation"][1], 1.0);  // hips at the T-pose height
  ASSERT_EQ(j["animations"][0]["channels"].size(), 3u);
  EXPECT_EQ(j["animations"][0]["channels"][1]["target"]["path"], "translation");
  EXPECT_EQ(j["accessors"][0]["max"][0].get<double>(), static_cast<double>(3.0f / 60.0f));
  // the BIN chunk holds (w, 0, 0) per key for each expression
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, glb.data() + 12, 4);
  const char* bin = glb.data() + 20 + json_length + 8;
  const auto& view = j["bufferViews"][j["accessors"][2]["bufferView"].get<int>()];
  float xyz[12];
  std::memcpy(xyz, bin + view["byteOffset"].get<std::size_t>(), sizeof xyz);
  EXPECT_EQ(xyz[3], 0.5f);
  EXPECT_EQ(xyz[4], 0.0f);
  EXPECT_EQ(xyz[6], 0.0f);
  EXPECT_TRUE(is_vrm_preset_expression("oh"));
  EXPECT_FALSE(is_vrm_preset_expression("O"));
  EXPECT_THROW(write_vrm_animation(std::vector<std::string>{"aa", "aa"}, Eigen::MatrixXf::Zero(1, 2), {60, 1}), std::invalid_argument);
}

TEST(TalkingHeadJson, VisemeRunsWordsAndTheAnimationTemplate) {
  const std::vector<OculusViseme> v{OculusViseme::kSil, OculusViseme::kPP, OculusViseme::kPP, OculusViseme::kAA};
  const std::vector<std::string> names{"jawOpen", "mouthClose"};
  Eigen::MatrixXf w(4, 2);
  w << 0, 0, 0.1f, 0, 0.2f, 0, 0.3f, 0;
  const std::vector<TimedText> words{{"ma", 16.0, 50.0}};
  const auto j = nlohmann::json::parse(talkinghead_json(words, v, names, w, {60, 1}));
  EXPECT_EQ(j["visemes"], (nlohmann::json{"sil", "PP", "aa"}));
  EXPECT_NEAR(j["vtimes"][1].get<double>(), 1000.0 / 60, 1e-9);
  EXPECT_NEAR(j["vdurations"][1].get<double>(), 2000.0 / 60, 1e-9);
  EXPECT_EQ(j["words"][0], "ma");
  EXPECT_EQ(j["anim"]["dt"].size(), 4u);
  EXPECT_TRUE(j["anim"]["vs"].contains("jawOpen"));
  EXPECT_FALSE(j["anim"]["vs"].contains("mouthClose"));  // all zero: left out
  EXPECT_FLOAT_EQ(j["anim"]["vs"]["jawOpen"][3].get<float>(), 0.3f);
}

TEST(OculusVisemes, EveryPhoneHasOneAndHhTakesTheNext) {
  EXPECT_EQ(*oculus_viseme(Phone::M), OculusViseme::kPP);
  EXPECT_EQ(*oculus_viseme(Phone::UW), OculusViseme::kOU);
  EXPECT_FALSE(oculus_viseme(Phone::HH).has_value());
  const std::vector<Phone> p{Phone::SIL, Phone::HH, Phone::HH, Phone::AA, Phone::HH};
  EXPECT_EQ(oculus_viseme_timeline(p),
            (std::vector<OculusViseme>{OculusViseme::kSil, OculusViseme::kAA, OculusViseme::kAA, OculusViseme::kAA, OculusViseme::kSil}));
  EXPECT_EQ(kOculusMorphNames[12], "viseme_I");
}

}  // namespace
}  // namespace fapcast
