// The avatar reader and writer: named bad avatars refused with their golden messages; a real
// avatar (Ready Player Me's, via TalkingHead: ARKit + Oculus morph targets, skinned, textured)
// animated by name with everything it had kept byte for byte.
#include "fapcast/rig/avatar_glb.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "fapcast/core/input_error.hpp"
#include "fapcast/rig/arkit_shapes.hpp"
#include "support/bad_inputs.hpp"

namespace fapcast {
namespace {

const std::string kAvatars = std::string(FAPCAST_TEST_DATA) + "/avatars";

std::vector<std::string> arkit_names() {
  std::vector<std::string> n;
  for (const ArkitShape& s : kArkitShapes) n.emplace_back(s.name);
  return n;
}

std::string error_of(const std::string& name, const std::string& bytes) {
  try {
    const Avatar a = read_avatar(bytes, name);
    animate_avatar(a, arkit_names(), Eigen::MatrixXf::Zero(2, 52), {60, 1}, "test");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(AvatarGlb, NamedBadAvatarsGiveTheirGoldenErrors) {
  const std::string dir = kAvatars + "/bad";
  const auto golden = test::golden_errors(dir);
  const auto names = test::bad_input_names(dir, ".glb");
  ASSERT_GE(names.size(), 12u);
  for (const std::string& name : names) {
    const std::string message = error_of(name, test::slurp(dir + "/" + name));
    EXPECT_NE(message.find(": " + test::rule_of(name) + ": "), std::string::npos) << message;
    ASSERT_TRUE(golden.count(name)) << name << " has no line in expected-errors.txt; it says: " << message;
    EXPECT_EQ(message, golden.at(name));
  }
}

struct Glb {
  nlohmann::json json;
  std::string bin;
};
Glb split(const std::string& bytes) {
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, bytes.data() + 12, 4);
  return {nlohmann::json::parse(bytes.substr(20, json_length)), bytes.substr(20 + json_length + 8)};
}

TEST(AvatarGlb, ARealAvatarGainsOneAnimationAndKeepsEverythingElse) {
  const std::string original = test::slurp(kAvatars + "/brunette-t.glb");
  const Avatar avatar = read_avatar(original, "brunette-t.glb");
  ASSERT_EQ(avatar.meshes.size(), 4u);  // head, teeth and two eyes carry the 67 targets
  for (const AvatarMesh& m : avatar.meshes) EXPECT_EQ(m.targets.size(), 67u) << m.name;
  const Eigen::Index frames = 30;
  Eigen::MatrixXf w(frames, 52);
  for (Eigen::Index f = 0; f < frames; ++f)
    for (Eigen::Index c = 0; c < 52; ++c) w(f, c) = static_cast<float>((f * 7 + c * 3) % 11) / 10.0f;
  const AvatarAnimation out = animate_avatar(avatar, arkit_names(), w, {60, 1}, "speech");
  EXPECT_EQ(out.driven.size(), 52u);
  EXPECT_EQ(out.unknown.size(), 15u);  // the Oculus visemes, held at rest
  const Glb before = split(original), after = split(out.bytes);
  for (const auto& [key, value] : before.json.items()) {
    if (key == "buffers") {  // one buffer, the BIN chunk: only its length grows
      EXPECT_EQ(value.size(), 1u);
      EXPECT_GT(after.json[key][0]["byteLength"].get<std::size_t>(), value[0]["byteLength"].get<std::size_t>());
    } else if (key == "bufferViews" || key == "accessors") {
      for (std::size_t i = 0; i < value.size(); ++i) EXPECT_EQ(after.json[key][i], value[i]) << key << " " << i;
    } else if (key != "animations") {
      EXPECT_EQ(after.json[key], value) << key;
    }
  }
  EXPECT_EQ(after.bin.substr(0, before.bin.size()), before.bin);
  const nlohmann::json& animation = after.json["animations"].back();
  EXPECT_EQ(animation["name"], "speech");
  EXPECT_EQ(animation["channels"].size(), 4u);
  // the head's weights, key 5: the ARKit columns in the head's target order, visemes at rest
  const AvatarMesh& head = avatar.meshes[2];
  ASSERT_EQ(head.name, "Wolf3D_Head");
  int sampler = -1;
  for (const auto& c : animation["channels"])
    if (after.json["nodes"][c["target"]["node"].get<int>()]["mesh"] == head.mesh) sampler = c["sampler"];
  ASSERT_GE(sampler, 0);
  const auto& accessor = after.json["accessors"][animation["samplers"][sampler]["output"].get<int>()];
  EXPECT_EQ(accessor["count"], static_cast<std::size_t>(frames) * 67);
  const auto& view = after.json["bufferViews"][accessor["bufferView"].get<int>()];
  std::vector<float> values(static_cast<std::size_t>(frames) * 67);
  std::memcpy(values.data(), after.bin.data() + view["byteOffset"].get<std::size_t>(), values.size() * sizeof(float));
  for (std::size_t t = 0; t < head.targets.size(); ++t) {
    const auto index = arkit_index(head.targets[t]);
    EXPECT_EQ(values[5 * 67 + t], index ? w(5, static_cast<Eigen::Index>(*index)) : 0.0f) << head.targets[t];
  }
  // the result reads back as an avatar
  EXPECT_EQ(read_avatar(out.bytes, "out.glb").meshes.size(), 4u);
}

}  // namespace
}  // namespace fapcast
