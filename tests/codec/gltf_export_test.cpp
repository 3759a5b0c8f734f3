// glTF binary export (spec/gltf.md): the .glb is read back with tinygltf's own loader and checked
// against what glTF 2.0 requires (accessor counts, POSITION min/max, key times, weights), its
// container is checked byte by byte, and read_glb round-trips it.
#include "fapcast/codec/gltf_export.hpp"

#include <tiny_gltf.h>

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "fapcast/core/input_error.hpp"

namespace fapcast {
namespace {

// A unit square of two triangles in the xy plane, two targets (lift one corner, push the other
// out) and five frames of weights.
MorphAnimation square(int frames = 5, FrameRate rate = {60, 1}) {
  MorphAnimation a;
  a.name = "square";
  a.base_positions_m.resize(3, 4);
  a.base_positions_m << 0, 1, 1, 0,  //
      0, 0, 1, 1,                     //
      0, 0, 0, 0;
  a.triangles.resize(3, 2);
  a.triangles << 0, 0,  //
      1, 2,             //
      2, 3;
  Eigen::Matrix3Xf lift = Eigen::Matrix3Xf::Zero(3, 4);
  lift(1, 2) = 0.25f;
  Eigen::Matrix3Xf push = Eigen::Matrix3Xf::Zero(3, 4);
  push(2, 3) = -0.5f;
  a.targets_m = {lift, push};
  a.target_names = {"lift", "push"};
  a.weights.resize(frames, 2);
  for (int f = 0; f < frames; ++f) {
    a.weights(f, 0) = static_cast<float>(f) / 7.0f;
    a.weights(f, 1) = 1.0f - static_cast<float>(f) / 3.0f;
  }
  a.rate = rate;
  return a;
}

tinygltf::Model load(const std::string& glb) {
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  EXPECT_TRUE(loader.LoadBinaryFromMemory(&m, &err, &warn, reinterpret_cast<const unsigned char*>(glb.data()),
                                          static_cast<unsigned int>(glb.size())))
      << err;
  EXPECT_EQ(warn, "");
  return m;
}

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

TEST(GltfExport, TinyGltfLoadsWhatTheSpecRequires) {
  const MorphAnimation a = square();
  const std::string glb = write_glb(a);
  const tinygltf::Model m = load(glb);
  ASSERT_EQ(m.meshes.size(), 1u);
  ASSERT_EQ(m.meshes[0].primitives.size(), 1u);
  const auto& p = m.meshes[0].primitives[0];
  EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
  const auto& pos = m.accessors[static_cast<std::size_t>(p.attributes.at("POSITION"))];
  EXPECT_EQ(pos.count, 4u);
  EXPECT_EQ(pos.type, TINYGLTF_TYPE_VEC3);
  EXPECT_EQ(pos.minValues, (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(pos.maxValues, (std::vector<double>{1, 1, 0}));
  EXPECT_EQ(m.accessors[static_cast<std::size_t>(p.indices)].count, 6u);
  ASSERT_EQ(p.targets.size(), 2u);
  for (const auto& t : p.targets) {
    const auto& acc = m.accessors[static_cast<std::size_t>(t.at("POSITION"))];
    EXPECT_EQ(acc.count, 4u);
    EXPECT_EQ(acc.minValues.size(), 3u);  // glTF: POSITION accessors, targets too, need min/max
    EXPECT_EQ(acc.maxValues.size(), 3u);
  }
  EXPECT_EQ(m.accessors[static_cast<std::size_t>(p.targets[0].at("POSITION"))].maxValues[1], 0.25);
  EXPECT_EQ(m.accessors[static_cast<std::size_t>(p.targets[1].at("POSITION"))].minValues[2], -0.5);
  EXPECT_EQ(m.meshes[0].weights, (std::vector<double>{0, 0}));
  ASSERT_EQ(m.meshes[0].extras.Get("targetNames").ArrayLen(), 2u);
  EXPECT_EQ(m.meshes[0].extras.Get("targetNames").Get(1).Get<std::string>(), "push");
  ASSERT_EQ(m.nodes.size(), 1u);
  EXPECT_EQ(m.nodes[0].mesh, 0);
  ASSERT_EQ(m.scenes.size(), 1u);

  ASSERT_EQ(m.animations.size(), 1u);
  const auto& anim = m.animations[0];
  ASSERT_EQ(anim.channels.size(), 1u);
  EXPECT_EQ(anim.channels[0].target_path, "weights");
  EXPECT_EQ(anim.channels[0].target_node, 0);
  const auto& sampler = anim.samplers[static_cast<std::size_t>(anim.channels[0].sampler)];
  EXPECT_EQ(sampler.interpolation, "LINEAR");
  const auto& input = m.accessors[static_cast<std::size_t>(sampler.input)];
  const auto& output = m.accessors[static_cast<std::size_t>(sampler.output)];
  EXPECT_EQ(input.count, 5u);
  EXPECT_EQ(output.count, 10u);  // F x K scalars
  ASSERT_EQ(input.minValues.size(), 1u);  // glTF: sampler input needs min/max
  EXPECT_EQ(input.maxValues[0], static_cast<double>(static_cast<float>(4.0 / 60.0)));
  const auto& buffer = m.buffers[0].data;
  const auto& in_view = m.bufferViews[static_cast<std::size_t>(input.bufferView)];
  const auto& out_view = m.bufferViews[static_cast<std::size_t>(output.bufferView)];
  for (int f = 0; f < 5; ++f) {
    float t, w0, w1;
    std::memcpy(&t, buffer.data() + in_view.byteOffset + 4 * f, 4);
    std::memcpy(&w0, buffer.data() + out_view.byteOffset + 8 * f, 4);
    std::memcpy(&w1, buffer.data() + out_view.byteOffset + 8 * f + 4, 4);
    EXPECT_EQ(t, static_cast<float>(f / 60.0)) << f;
    EXPECT_EQ(w0, a.weights(f, 0)) << f;
    EXPECT_EQ(w1, a.weights(f, 1)) << f;
  }
}

// The GLB container by hand: magic, version, total length, 4-byte aligned JSON then BIN chunk,
// and no buffer-view target on animation data (the validator rejects one).
TEST(GltfExport, ContainerIsWellFormed) {
  const std::string glb = write_glb(square());
  ASSERT_GE(glb.size(), 28u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_EQ(u32(glb, 4), 2u);
  EXPECT_EQ(u32(glb, 8), glb.size());
  const std::uint32_t json_length = u32(glb, 12);
  EXPECT_EQ(u32(glb, 16), 0x4E4F534Au);  // "JSON"
  EXPECT_EQ(json_length % 4, 0u);
  const std::size_t bin = 20 + json_length;
  EXPECT_EQ(u32(glb, bin + 4), 0x004E4942u);  // "BIN\0"
  EXPECT_EQ(bin + 8 + u32(glb, bin), glb.size());
  const auto json = nlohmann::json::parse(glb.substr(20, json_length));
  EXPECT_EQ(json["asset"]["version"], "2.0");
  for (const auto& sampler : json["animations"][0]["samplers"])
    for (const char* key : {"input", "output"}) {
      const auto view = json["accessors"][sampler[key].get<int>()]["bufferView"].get<int>();
      EXPECT_FALSE(json["bufferViews"][view].contains("target"));
    }
  for (const auto& view : json["bufferViews"]) EXPECT_EQ(view.value("byteOffset", 0) % 4, 0);
}

TEST(GltfExport, ReadGlbRoundTrips) {
  for (const FrameRate rate : {FrameRate{60, 1}, FrameRate{25, 1}, FrameRate{30000, 1001}}) {
    SCOPED_TRACE(rate.fps());
    MorphAnimation a = square(9, rate);
    a.normals = Eigen::Matrix3Xf::Zero(3, 4);
    a.normals->row(2).setOnes();
    const MorphAnimation b = read_glb(write_glb(a), "square.glb");
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.base_positions_m, a.base_positions_m);
    EXPECT_EQ(b.triangles, a.triangles);
    ASSERT_TRUE(b.normals.has_value());
    EXPECT_EQ(*b.normals, *a.normals);
    ASSERT_EQ(b.targets_m.size(), 2u);
    EXPECT_EQ(b.targets_m[1], a.targets_m[1]);
    EXPECT_EQ(b.target_names, a.target_names);
    EXPECT_EQ(b.weights, a.weights);
    EXPECT_EQ(b.rate, rate);
  }
}

TEST(GltfExport, WithoutFramesThereIsNoAnimation) {
  const MorphAnimation b = read_glb(write_glb(square(0)), "still.glb");
  EXPECT_EQ(b.weights.rows(), 0);
  EXPECT_EQ(b.targets_m.size(), 2u);
  EXPECT_TRUE(load(write_glb(square(0))).animations.empty());
}

TEST(GltfExport, FramePositionsBlendTheTargets) {
  const MorphAnimation a = square();
  const Eigen::Matrix3Xf p = frame_positions(a, 3);
  EXPECT_FLOAT_EQ(p(1, 2), 1.0f + 0.25f * a.weights(3, 0));
  EXPECT_FLOAT_EQ(p(2, 3), -0.5f * a.weights(3, 1));
  EXPECT_EQ(p(0, 1), 1.0f);
}

TEST(GltfExport, RefusesInconsistentInput) {
  MorphAnimation a = square();
  a.weights.resize(5, 3);
  EXPECT_THROW(write_glb(a), std::invalid_argument);
  a = square();
  a.triangles(0, 0) = 4;
  EXPECT_THROW(write_glb(a), std::invalid_argument);
  a = square();
  a.targets_m[0].resize(3, 3);
  EXPECT_THROW(write_glb(a), std::invalid_argument);
  a = square();
  a.weights(1, 1) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(write_glb(a), std::invalid_argument);
  a = square();
  a.rate = {0, 1};
  EXPECT_THROW(write_glb(a), std::invalid_argument);
}

TEST(GltfExport, ReadGlbNamesTheRuleBroken) {
  const auto rule_of = [](const std::string& bytes) {
    try {
      (void)read_glb(bytes, "bad.glb");
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().source, "bad.glb");
      return e.rule();
    }
    return std::string("accepted");
  };
  const std::string glb = write_glb(square());
  EXPECT_EQ(rule_of("not a glb at all"), "glb-container");
  EXPECT_EQ(rule_of(glb.substr(0, glb.size() - 40)), "glb-container");
  std::string flipped = glb;
  flipped[8] ^= 0x10;  // total length
  EXPECT_EQ(rule_of(flipped), "glb-container");
  // A BIN chunk that claims 8 more bytes than the file has (tinygltf 2.7 would read past it).
  std::string overrun = glb;
  const std::size_t bin = 20 + u32(glb, 12);
  const std::uint32_t longer = u32(glb, bin) + 8;
  std::memcpy(overrun.data() + bin, &longer, 4);
  EXPECT_EQ(rule_of(overrun), "glb-container");
  // Valid container, broken JSON.
  std::string json = glb;
  json[20] = '[';
  EXPECT_EQ(rule_of(json), "glb-syntax");
  // Key times 1/1,310,000 s apart (the fuzzer's input of issue #17: it read as 1.31 MHz, wrote
  // back other times and `render` took it): outside the 1..1000 fps a .glb may claim.
  EXPECT_EQ(rule_of(write_glb(square(5, {1'310'000, 1}))), "gltf-frame-rate");
  EXPECT_EQ(rule_of(write_glb(square(5, {1001, 1}))), "gltf-frame-rate");
  // A rate at the bound reads back as itself; ten minutes at 1000 fps are past float key times.
  EXPECT_EQ(read_glb(write_glb(square(5, {1000, 1})), "k.glb").rate, (FrameRate{1000, 1}));
  EXPECT_EQ(rule_of(write_glb(square(600'000, {1000, 1}))), "gltf-key-times");
}

}  // namespace
}  // namespace fapcast

namespace fapcast {
namespace {

// A file from another writer (Python json + struct, tests/data/PROVENANCE.md).
TEST(GltfExport, ReadsAGlbFromAnotherWriter) {
  const std::string path = std::string(FAPCAST_TEST_DATA) + "/gltf/square-2-targets-3-frames.glb";
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const MorphAnimation a = read_glb(bytes, path);
  EXPECT_EQ(a.name, "square");
  EXPECT_EQ(a.base_positions_m.cols(), 4);
  EXPECT_EQ(a.triangles.cols(), 2);
  ASSERT_EQ(a.targets_m.size(), 2u);
  EXPECT_EQ(a.targets_m[0](1, 2), 0.25f);
  EXPECT_EQ(a.target_names, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(a.rate, (FrameRate{60, 1}));
  ASSERT_EQ(a.weights.rows(), 3);
  EXPECT_EQ(a.weights(1, 0), 0.5f);
  EXPECT_EQ(a.weights(2, 0), 1.0f);
  // And writing it again gives a file that reads back the same.
  const MorphAnimation b = read_glb(write_glb(a), "again.glb");
  EXPECT_EQ(b.targets_m[1], a.targets_m[1]);
  EXPECT_EQ(b.weights, a.weights);
}


// Inputs the fuzzer found (tests/data/gltf/fuzz-regressions/glb.NNN.<rule>.glb, also seeds of
// glb_fuzz): each is refused with the rule in its name. glb.001: key times 1/1,310,000 s apart,
// which read as 1.31 MHz, did not survive write-then-read, and `render` took (issue #17).
TEST(GltfExport, RefusesTheFuzzersInputs) {
  const std::filesystem::path dir = std::filesystem::path(FAPCAST_TEST_DATA) / "gltf" / "fuzz-regressions";
  int seen = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();  // glb.NNN.<rule>.glb
    const std::string rule = name.substr(8, name.size() - 8 - 4);
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
      (void)read_glb(bytes, name);
      ADD_FAILURE() << name << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.rule(), rule) << e.what();
    }
    ++seen;
  }
  EXPECT_GE(seen, 1);
}

}  // namespace
}  // namespace fapcast
