#include "fapcast/codec/bvh_text.hpp"

#include "fapcast/core/input_error.hpp"
#include "support/bad_inputs.hpp"
#include "support/fap_sequences.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <sstream>

namespace fapcast {
namespace {

namespace fs = std::filesystem;
const fs::path kDir = fs::path(FAPCAST_TEST_DATA) / "bvh";

using test::slurp;

TEST(BvhText, ReadsTheSmallFixture) {
  const BvhDocument doc = read_bvh(slurp(kDir / "small.bvh"), "small.bvh");
  ASSERT_EQ(doc.joints.size(), 2u);
  EXPECT_EQ(doc.joints[1].name, "jaw");
  EXPECT_EQ(doc.joints[1].parent, 0);
  EXPECT_EQ(doc.joints[1].offset, Eigen::Vector3d(0, 1.5, 2));
  EXPECT_EQ(doc.joints[1].channels,
            (std::vector{BvhChannel::kZrotation, BvhChannel::kXrotation, BvhChannel::kYrotation}));
  EXPECT_EQ(doc.joints[1].end_site, Eigen::Vector3d(0, -9, 7.6));
  EXPECT_EQ(doc.frame_count, 2u);
  EXPECT_EQ(doc.frame_time_s, 0.04);
  EXPECT_EQ(doc.channel_count(), 9u);
  const std::vector<double> second(doc.frame(1).begin(), doc.frame(1).end());
  EXPECT_EQ(second, (std::vector<double>{0, 0, 0, 1.5, -2, 0.25, 0, 10, 0}));
}

// Spellings other writers use that must read to the same document.
struct Variant {
  std::string name;
  std::function<std::string(std::string)> apply;
};
std::ostream& operator<<(std::ostream& out, const Variant& v) { return out << v.name; }

using test::replace_all;

class BvhTextVariant : public testing::TestWithParam<Variant> {};

TEST_P(BvhTextVariant, ReadsLikeTheCanonicalFile) {
  const std::string text = slurp(kDir / "small.bvh");
  EXPECT_EQ(read_bvh(GetParam().apply(text), "variant.bvh"), read_bvh(text, "small.bvh"));
}

INSTANTIATE_TEST_SUITE_P(
    Dialects, BvhTextVariant,
    testing::Values(
        Variant{"crlf", [](std::string s) { return replace_all(s, "\n", "\r\n"); }},
        Variant{"lone_cr", [](std::string s) { return replace_all(s, "\n", "\r"); }},
        Variant{"tabs", [](std::string s) { return replace_all(s, "  ", "\t"); }},
        Variant{"blank_lines", [](std::string s) { return replace_all(s, "\n", "\n\n  \n"); }},
        Variant{"lower_case_keywords",
                [](std::string s) {
                  for (const char* k : {"HIERARCHY", "ROOT", "OFFSET", "CHANNELS", "JOINT",
                                        "End Site", "MOTION", "Frames:", "Frame Time:",
                                        "Xposition", "Zrotation"}) {
                    std::string lower = k;
                    for (char& c : lower) c = static_cast<char>(std::tolower(c));
                    s = replace_all(s, k, lower);
                  }
                  return s;
                }},
        Variant{"named_end_site", [](std::string s) { return replace_all(s, "End Site", "End Site chin"); }},
        Variant{"explicit_plus_and_exponents",
                [](std::string s) {
                  return replace_all(replace_all(s, " 1.5 ", " +1.5 "), " 10 ", " 1e1 ");
                }},
        Variant{"no_final_newline", [](std::string s) { return s.substr(0, s.size() - 1); }}),
    [](const auto& info) { return info.param.name; });

// Every named bad input fails with the rule its name gives and the message in the golden list.
class BvhBadInput : public testing::TestWithParam<std::string> {};

TEST_P(BvhBadInput, FailsWithItsRuleAndTheGoldenMessage) {
  const std::string name = GetParam();
  try {
    read_bvh(slurp(kDir / "bad" / name), name);
    FAIL() << name << " was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), test::rule_of(name));
    EXPECT_EQ(e.where().source, name);
    EXPECT_TRUE(e.where().line.has_value());
    EXPECT_EQ(e.what(), test::golden_errors(kDir / "bad")[name]);
  }
}

INSTANTIATE_TEST_SUITE_P(Named, BvhBadInput,
                         testing::ValuesIn(test::bad_input_names(kDir / "bad", ".bvh")),
                         [](const auto& info) { return test::test_name_of(info.param); });

TEST(BvhText, GoldenListCoversExactlyTheBadInputs) {
  const auto golden = test::golden_errors(kDir / "bad");
  const auto names = test::bad_input_names(kDir / "bad", ".bvh");
  EXPECT_EQ(golden.size(), names.size());
  for (const std::string& name : names) EXPECT_TRUE(golden.count(name)) << name;
}


// A random well-formed document: random tree, channel subsets in random order, values of every
// magnitude a rig produces, a random frame time.
BvhDocument random_document(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> joints_n(1, 20), channels_n(0, 6), frames_n(0, 12);
  std::uniform_real_distribution<double> value(-500.0, 500.0);
  BvhDocument doc;
  const int n = joints_n(rng);
  std::vector<int> path;  // the open joints, root first
  for (int i = 0; i < n; ++i) {
    BvhJoint j;
    j.name = "j" + std::to_string(i);
    if (i > 0) {
      path.resize(std::uniform_int_distribution<std::size_t>(1, path.size())(rng));
      j.parent = path.back();
    }
    j.offset = {value(rng), value(rng) * 1e-6, value(rng) * 1e6};
    std::vector<BvhChannel> all{BvhChannel::kXposition, BvhChannel::kYposition,
                                BvhChannel::kZposition, BvhChannel::kXrotation,
                                BvhChannel::kYrotation, BvhChannel::kZrotation};
    std::shuffle(all.begin(), all.end(), rng);
    all.resize(static_cast<std::size_t>(channels_n(rng)));
    j.channels = all;
    doc.joints.push_back(j);
    path.push_back(i);
  }
  if (doc.channel_count() == 0) doc.joints[0].channels = {BvhChannel::kZrotation};
  // Leaves (no joint names them as parent) may carry an End Site.
  std::vector<bool> has_child(doc.joints.size(), false);
  for (const BvhJoint& j : doc.joints)
    if (j.parent >= 0) has_child[static_cast<std::size_t>(j.parent)] = true;
  for (std::size_t i = 0; i < doc.joints.size(); ++i)
    if (!has_child[i] && rng() % 2) doc.joints[i].end_site = Eigen::Vector3d{0, value(rng), 1};
  doc.frame_count = static_cast<std::uint64_t>(frames_n(rng));
  doc.frame_time_s = 1.0 / std::uniform_int_distribution<int>(1, 120)(rng);
  for (std::size_t i = 0; i < doc.frame_count * doc.channel_count(); ++i)
    doc.motion.push_back(value(rng) * std::pow(10.0, static_cast<int>(rng() % 13) - 6));
  return doc;
}

TEST(BvhText, RandomDocumentsRoundTripExactly) {
  const std::uint64_t s = test::test_seed(test::kFapSequenceSeed);
  std::mt19937_64 rng(s);
  for (int i = 0; i < 300; ++i) {
    const BvhDocument doc = random_document(rng);
    const std::string text = write_bvh(doc);
    ASSERT_EQ(read_bvh(text, "random.bvh"), doc)
        << "document " << i << "; reproduce with FAPCAST_SEED=" << s
        << " fapcast_codec_tests --gtest_filter=BvhText.RandomDocumentsRoundTripExactly\n"
        << text;
    // Writing is deterministic and idempotent through a read.
    ASSERT_EQ(write_bvh(read_bvh(text, "random.bvh")), text);
  }
}

TEST(BvhText, WriterRefusesDocumentsThatBreakItsInvariants) {
  BvhDocument ok;
  ok.joints.push_back({"root", -1, {0, 0, 0}, {BvhChannel::kXrotation}, {}});
  ok.joints.push_back({"child", 0, {0, 1, 0}, {BvhChannel::kXrotation}, {}});
  ok.frame_count = 1;
  ok.motion = {1, 2};
  EXPECT_NO_THROW(write_bvh(ok));
  auto refused = [](BvhDocument d) { EXPECT_THROW(write_bvh(d), std::invalid_argument); };
  refused(BvhDocument{});  // no joints
  BvhDocument d = ok;
  d.joints[1].name = "two words";
  refused(d);
  d = ok;
  d.joints[1].name = "root";
  refused(d);
  d = ok;
  d.motion.pop_back();
  refused(d);
  d = ok;
  d.joints[1].parent = -1;  // a second root
  refused(d);
  d = ok;
  d.joints[0].end_site = Eigen::Vector3d{0, 1, 0};  // End Site on a joint with children
  refused(d);
  d = ok;
  d.motion[0] = std::numeric_limits<double>::infinity();
  refused(d);
}

TEST(BvhText, WrittenLayoutIsWhatBlendersImporterReadsLineByLine) {
  // Blender's importer reads OFFSET two lines after ROOT/JOINT and CHANNELS on the next line.
  BvhDocument doc;
  doc.joints.push_back({"head", -1, {0, 0, 0}, {BvhChannel::kZrotation}, Eigen::Vector3d{0, 1, 0}});
  doc.frame_count = 1;
  doc.motion = {0.5};
  EXPECT_EQ(write_bvh(doc),
            "HIERARCHY\nROOT head\n{\n\tOFFSET 0 0 0\n\tCHANNELS 1 Zrotation\n\tEnd Site\n\t{\n"
            "\t\tOFFSET 0 1 0\n\t}\n}\nMOTION\nFrames: 1\nFrame Time: 0.04\n0.5\n");
}

}  // namespace
}  // namespace fapcast
