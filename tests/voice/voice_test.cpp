// Voice::open on a hand-made complete voice, and its refusals beyond the container's rules (named
// fixtures in tests/data/voice/bad-voice/, golden messages in EXPECTED.txt there).
#include "fapcast/voice/voice.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>

#include "fapcast/core/crc32.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/voice/voice_graph.hpp"
#include "fapcast/core/file_io.hpp"
#include "support/bad_inputs.hpp"
#include "support/tiny_voice.hpp"

namespace fapcast {
namespace {

namespace vs = voice_section;
using fapcast::test::TinyVoice;
const std::filesystem::path kBad = std::filesystem::path(FAPCAST_TEST_DATA) / "voice" / "bad-voice";

std::string full_voice_refusal(const std::filesystem::path& file) {
  try {
    (void)Voice::open(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Voice, OpensACompleteVoiceAndHandsOutItsParts) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "fapcast_tiny_full_voice.fapv";
  write_file_atomically(file, TinyVoice().bytes());
  Voice moved = Voice::open(file);
  const Voice voice = std::move(moved);  // move-only; the mapping moves with it
  EXPECT_EQ(voice.provenance(), TinyVoice().provenance);
  EXPECT_EQ(voice.component_count(), 1);
  EXPECT_EQ(voice.dimension(), 9);
  EXPECT_EQ(voice.pca_mean()(0, 8), 8.f);
  EXPECT_EQ(voice.pca_components()(0, 1), 1.f);
  EXPECT_EQ(voice.frame_coefficients().rows(), 3);
  EXPECT_EQ(voice.frame_coefficients()(1, 0), -0.5f);
  ASSERT_EQ(voice.graph().size(), 2u);
  EXPECT_EQ(voice.graph().state(1).viseme, VisemeClass::kBilabial);
  EXPECT_TRUE(voice.graph().has_join_features());
  ASSERT_EQ(voice.state_phones().size(), 2u);
  EXPECT_EQ(voice.state_phones()[1], Phone::M);
  EXPECT_EQ(voice.graph().entries(VisemeClass::kSilence, VisemeClass::kBilabial).size(), 1u);
  ASSERT_EQ(voice.feature_points().size(), 1u);
  EXPECT_EQ(voice.feature_points()[0].label, "8.1");
  EXPECT_EQ(voice.feature_points()[0].neutral_m, Eigen::Vector3d(0.0, -0.02, 0.1));
  ASSERT_EQ(voice.rigid_markers().size(), 3u);
  EXPECT_EQ(voice.rigid_markers()[2].source_reference_m, Eigen::Vector3d(0.0, 0.04, 0.1));
  EXPECT_EQ(voice.retarget_map().centre_count(), 2);
  EXPECT_FALSE(voice.face_maps().has_value()) << "a voice on its own face has no FMAP";
  EXPECT_EQ(voice.retarget_map().lambda(), 1e-6);
  // The map evaluates: at the first centre, vertex 0's y is offset + w0 phi0 + w1 phi1.
  const Eigen::VectorXd y = voice.retarget_map()(Eigen::Vector3d::Zero());
  EXPECT_NEAR(y(1), 1.0 + 1.0 - std::exp(-1e-4 / 1e-4), 1e-6);
  std::filesystem::remove(file);
}

// The lip-contact term (LCSH + LCON) is read with the map: at the source's contact the whole
// retargeting closes the target's lips by the term's amount of the shape.
TEST(Voice, RetargetsWithTheLipContactTermWhenItHasOne) {
  TinyVoice tiny;
  EXPECT_FALSE(tiny.open("fapcast_tiny_no_contact.fapv").retargeting().contact().has_value());
  tiny.set_inner_lips_with_contact();
  // The voice_open fuzz target's seed for the term's checks is this voice.
  const std::filesystem::path seed = std::filesystem::path(FAPCAST_SOURCE_DIR) / "tests" / "fuzz" / "corpus" /
                                     "voice_open_fuzz" / "tiny-with-lip-contact.fapv";
  if (std::getenv("FAPCAST_REGENERATE")) write_file_atomically(seed, tiny.bytes());
  EXPECT_EQ(read_file(seed), tiny.bytes()) << seed << " is stale: regenerate";
  const Voice voice = tiny.open("fapcast_tiny_contact.fapv");
  const Retargeting& retarget = voice.retargeting();
  ASSERT_TRUE(retarget.contact().has_value());
  EXPECT_EQ(retarget.contact()->source_upper, 0);
  EXPECT_EQ(retarget.contact()->source_lower, 3);
  EXPECT_EQ(retarget.response_count(), 3);
  Eigen::VectorXd touching = Eigen::VectorXd::Zero(6);
  touching(4) = -0.0005;  // 2.3 half a millimetre below 2.2: the term's source contact
  const double amount = 0.006 / 0.008;  // the map leaves the target's lips 6 mm apart
  const Eigen::VectorXd y = retarget(touching), mapped = voice.retarget_map()(touching);
  EXPECT_NEAR(y(1) - mapped(1), -0.004 * amount, 1e-9);
  EXPECT_NEAR(y(4) - mapped(4), 0.004 * amount, 1e-9);
  Eigen::VectorXd apart = touching;
  apart(4) = -0.009;  // 9 mm: no term
  EXPECT_NEAR((retarget(apart) - voice.retarget_map()(apart)).norm(), 0.0, 1e-12);
}

// ---- named bad voices: tests/data/voice/bad-voice/bad.NNN.<rule>[.<what>].fapv ----

struct BadFullVoiceCase {
  std::string name;
  std::function<std::string()> make;
};

// After editing section `index`'s bytes in place: its CRC, the table's and the header's again.
void reseal(std::string& b, std::size_t index) {
  const auto all = std::as_bytes(std::span(b));
  const std::size_t entry = 64 + 48 * index;
  std::uint64_t offset = 0, size = 0;
  std::uint32_t count = 0;
  std::memcpy(&offset, b.data() + entry + 24, 8);
  std::memcpy(&size, b.data() + entry + 32, 8);
  std::memcpy(&count, b.data() + 12, 4);
  const std::uint32_t section = crc32(all.subspan(offset, size));
  std::memcpy(b.data() + entry + 40, &section, 4);
  const std::uint32_t table = crc32(all.subspan(64, 48 * std::size_t{count}));
  std::memcpy(b.data() + 24, &table, 4);
  const std::uint32_t header = crc32(all.first(28));
  std::memcpy(b.data() + 28, &header, 4);
}

// Section indices in TinyVoice::bytes() order.
constexpr std::size_t kProvIndex = 0, kRparIndex = 8, kGrphIndex = 9;

std::vector<BadFullVoiceCase> bad_full_voices() {
  std::vector<BadFullVoiceCase> out;
  const auto with = [](std::function<void(TinyVoice&)> change) {
    return [change] {
      TinyVoice v;
      change(v);
      return v.bytes();
    };
  };
  const auto patched = [](std::size_t index, std::function<void(std::string&, std::uint64_t offset)> patch) {
    return [index, patch] {
      std::string b = TinyVoice().bytes();
      std::uint64_t offset = 0;
      std::memcpy(&offset, b.data() + 64 + 48 * index + 24, 8);
      patch(b, offset);
      reseal(b, index);
      return b;
    };
  };
  out.push_back({"bad.001.missing-section.FPNT.fapv", with([](TinyVoice& v) { v.skip = vs::kFeaturePoints; })});
  out.push_back({"bad.002.feature-points.not-json.fapv", with([](TinyVoice& v) { v.feature_points = "[1, 2"; })});
  out.push_back({"bad.003.feature-points.vertex.fapv", with([](TinyVoice& v) {
                   v.feature_points.replace(v.feature_points.find("\"vertex\": 0"), 11, "\"vertex\": 3");
                 })});
  out.push_back({"bad.004.feature-points.count.fapv", with([](TinyVoice& v) {
                   v.feature_points = voice_feature_points_json({}, {});
                 })});
  out.push_back({"bad.005.graph-version.fapv",
                 patched(kGrphIndex, [](std::string& b, std::uint64_t at) { b[at] = 1; })});  // the 40-phone layout
  out.push_back({"bad.006.section-shape.GRPH-frames.fapv", with([](TinyVoice& v) {
                   v.coefficients = RowMajorMatrixXf{{0.5f}, {-0.5f}, {0.f}, {1.f}};  // 4 frames, the graph has 3
                 })});
  out.push_back({"bad.007.provenance-field.notes.fapv", patched(kProvIndex, [](std::string& b, std::uint64_t) {
                   const std::string from = "\"prototype_rule\": \"by hand\"", to = "\"prototype_rule\": 12345678";
                   b.replace(b.find(from), from.size(), to + std::string(from.size() - to.size(), ' '));
                 })});
  out.push_back({"bad.008.rbf-scalars.fapv", patched(kRparIndex, [](std::string& b, std::uint64_t at) {
                   const double zero = 0.0;  // r^2 = 0
                   std::memcpy(b.data() + at, &zero, 8);
                 })});
  out.push_back({"bad.009.section-shape.FMAP.fapv", with([](TinyVoice& v) {
                   v.face_maps = RowMajorMatrixXf::Zero(3, 8);  // a 3 x 3 map per vertex is 9 numbers
                 })});
  out.push_back({"bad.010.non-finite.FMAP.fapv", with([](TinyVoice& v) {
                   v.face_maps = RowMajorMatrixXf::Identity(3, 9);
                   (*v.face_maps)(2, 4) = std::numeric_limits<float>::quiet_NaN();
                 })});
  out.push_back({"bad.011.missing-section.LCON.fapv", with([](TinyVoice& v) {
                   v.set_inner_lips_with_contact();
                   v.lip_contact.reset();  // the shape without its amounts
                 })});
  out.push_back({"bad.012.section-shape.LCON.fapv", with([](TinyVoice& v) {
                   v.set_inner_lips_with_contact();
                   v.lip_contact = RowMajorMatrixXd::Zero(1, 6);  // 5 scalars and 2 gap weights are 7
                 })});
  out.push_back({"bad.013.lip-contact.shape-opens.fapv", with([](TinyVoice& v) {
                   v.set_inner_lips_with_contact();
                   (*v.lip_contact)(0, 1) = 0.008;  // a shape that parts the lips
                 })});
  out.push_back({"bad.014.lip-contact.no-inner-lips.fapv", with([](TinyVoice& v) {
                   v.set_inner_lips_with_contact();
                   v.set_neutral_face(Eigen::Matrix3Xf::Zero(3, 3));  // back to 8.1 alone
                   v.source_points = 1;
                 })});
  return out;
}

std::map<std::string, std::string> full_voice_golden() { return test::golden_lines(kBad / "EXPECTED.txt"); }

class BadFullVoice : public ::testing::TestWithParam<BadFullVoiceCase> {};

TEST_P(BadFullVoice, IsRefusedWithTheGoldenMessage) {
  const BadFullVoiceCase& bad = GetParam();
  const std::filesystem::path file = kBad / bad.name;
  if (std::getenv("FAPCAST_REGENERATE") != nullptr) {
    std::filesystem::create_directories(kBad);
    write_file_atomically(file, bad.make());
    std::ofstream(kBad / "EXPECTED.txt", std::ios::app) << full_voice_refusal(file).substr(kBad.string().size() + 1) << "\n";
    return;
  }
  ASSERT_EQ(read_file(file), bad.make()) << bad.name << " is stale: regenerate";
  const std::string message = full_voice_refusal(file);
  const std::string rule = bad.name.substr(8, bad.name.find('.', 8) - 8);
  EXPECT_NE(message.find(file.string() + ": byte "), std::string::npos) << message;
  EXPECT_NE(message.find(": " + rule + ": "), std::string::npos) << message;
  const auto expected = full_voice_golden();
  ASSERT_TRUE(expected.count(bad.name)) << "no golden line for " << bad.name;
  EXPECT_EQ(message.substr(kBad.string().size() + 1), expected.at(bad.name));
}

INSTANTIATE_TEST_SUITE_P(Named, BadFullVoice, ::testing::ValuesIn(bad_full_voices()), [](const auto& info) {
  std::string n = info.param.name;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
});

// The container's own named bad voices are refused by Voice::open too, with the same rule.
TEST(Voice, RefusesTheContainersBadVoices) {
  const std::filesystem::path dir = std::filesystem::path(FAPCAST_TEST_DATA) / "voice" / "bad";
  int seen = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".fapv") continue;
    ++seen;
    const std::string name = entry.path().filename().string();
    const std::string rule = name.substr(8, name.find('.', 8) - 8);
    EXPECT_NE(full_voice_refusal(entry.path()).find(": " + rule + ": "), std::string::npos) << name;
  }
  EXPECT_GE(seen, 29);
}

}  // namespace
}  // namespace fapcast

namespace fapcast {
namespace {

// Voice::over_bytes runs open's checks on memory: it accepts the tiny voice (and the voice_open
// fuzz target's seed, which is that voice with face maps) and refuses what open refuses.
TEST(Voice, OverBytesChecksWhatOpenChecks) {
  test::TinyVoice tiny;
  tiny.face_maps = RowMajorMatrixXf::Identity(3, 9);
  const std::string bytes = tiny.bytes();
  const std::filesystem::path seed =
      std::filesystem::path(FAPCAST_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / "voice_open_fuzz" / "tiny-with-fmap.fapv";
  if (std::getenv("FAPCAST_REGENERATE")) write_file_atomically(seed, bytes);
  for (const std::string& b : {bytes, read_file(seed)}) {
    std::vector<std::uint64_t> aligned(b.size() / 8 + 1);
    std::memcpy(aligned.data(), b.data(), b.size());
    const Voice voice = Voice::over_bytes({reinterpret_cast<const std::byte*>(aligned.data()), b.size()}, "<memory>");
    EXPECT_EQ(voice.component_count(), 1);
    ASSERT_TRUE(voice.face_maps().has_value());
    EXPECT_EQ(voice.face_maps()->cols(), 9);
  }
  const std::string bad = read_file(kBad / "bad.010.non-finite.FMAP.fapv");
  std::vector<std::uint64_t> aligned(bad.size() / 8 + 1);
  std::memcpy(aligned.data(), bad.data(), bad.size());
  try {
    (void)Voice::over_bytes({reinterpret_cast<const std::byte*>(aligned.data()), bad.size()}, "bad.fapv");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "non-finite") << e.what();
  }
}

}  // namespace
}  // namespace fapcast
