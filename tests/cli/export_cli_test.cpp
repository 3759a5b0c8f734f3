// `fapcast export` end to end on the vendored Xface samples: BVH and JSON outputs read back with
// the codec's readers and agree with the .fap they came from; usage and input errors exit 2 and
// 1 and leave no output behind.
#include "fapcast/codec/bvh_export.hpp"
#include "fapcast/codec/bvh_text.hpp"
#include "fapcast/codec/face_geometry.hpp"
#include "fapcast/codec/fap_text.hpp"
#include "fapcast/codec/json_export.hpp"
#include "fapcast/core/file_io.hpp"
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace fapcast {
namespace {

namespace fs = std::filesystem;
using test::fapcast;
using test::run_command;

const std::string kXface = std::string(FAPCAST_TEST_DATA) + "/xface/";

class ExportXface : public testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    dir_ = test::make_temp_dir("export");
    fap_ = kXface + GetParam() + ".fap";
    track_ = read_fap_text(read_file(fap_), fap_).sequence;
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string dir_, fap_;
  FapSequence track_;
};

TEST_P(ExportXface, BvhHasOneMotionLinePerFrameAndTheJawFollowsOpenJaw) {
  const std::string out = dir_ + "/out.bvh";
  const auto r = run_command(fapcast("export '" + fap_ + "' -o '" + out + "'"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const BvhDocument doc = read_bvh(read_file(out), out);
  ASSERT_EQ(doc.frame_count, track_.frames.size());
  EXPECT_DOUBLE_EQ(doc.frame_time_s, 1.0 / track_.rate.fps());
  const auto face = generic_adult_face();
  const auto fapu = measure_fapu(face.feature_points);
  for (std::uint64_t k = 0; k < doc.frame_count; ++k) {
    // jaw: channels 6..11, Xrotation is its 5th channel (Zrotation Xrotation Yrotation).
    EXPECT_NEAR(doc.frame(k)[10],
                jaw_angle_deg(track_.frames[k].value(3), fapu.mns, face.jaw_length()),
                1e-12)
        << "frame " << k;
  }
  EXPECT_EQ(doc, fap_to_bvh(track_, face));  // the CLI adds nothing of its own
}

TEST_P(ExportXface, JsonCarriesTheTrackExactlyWithSamplePositions) {
  const std::string out = dir_ + "/out.json";
  const auto r = run_command(fapcast("export '" + fap_ + "' -o '" + out + "' --sample-rate 16000"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const FapJsonRead back = read_fap_json(read_file(out), out);
  EXPECT_EQ(back.sequence, track_);
  EXPECT_EQ(back.options.sample_rate, SampleRate{16000});
  EXPECT_EQ(back.options.generator.rfind("fapcast ", 0), 0u) << back.options.generator;

  // JSON in, BVH out gives the same file as .fap in, BVH out.
  const auto via_json = run_command(fapcast("export '" + out + "' -o '" + dir_ + "/a.bvh'"));
  const auto via_fap = run_command(fapcast("export '" + fap_ + "' -o '" + dir_ + "/b.bvh'"));
  ASSERT_EQ(via_json.exit_code, 0) << via_json.err;
  ASSERT_EQ(via_fap.exit_code, 0) << via_fap.err;
  EXPECT_EQ(read_file(dir_ + "/a.bvh"), read_file(dir_ + "/b.bvh"));
}

INSTANTIATE_TEST_SUITE_P(Samples, ExportXface,
                         testing::Values("anger", "beg", "disgust", "fear", "happy-for", "hate",
                                         "joy", "pride"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

TEST(ExportCli, UnknownOutputExtensionIsAUsageErrorAndWritesNothing) {
  const std::string dir = test::make_temp_dir("export-usage");
  const auto r = run_command(fapcast("export '" + kXface + "joy.fap' -o '" + dir + "/joy.txt'"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("must end in .bvh or .json"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(ExportCli, UnknownInputExtensionAndSampleRateForBvhAreUsageErrors) {
  const std::string dir = test::make_temp_dir("export-usage");
  EXPECT_EQ(run_command(fapcast("export '" + dir + "/x.wav' -o '" + dir + "/x.bvh'")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("export '" + kXface + "joy.fap' -o '" + dir +
                                "/x.bvh' --sample-rate 16000")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("export '" + kXface + "joy.fap' -o '" + dir +
                                "/x.json' --sample-rate 0")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("export '" + kXface + "joy.fap'")).exit_code, 2);  // no -o
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(ExportCli, BadInputExitsOneNamesTheFileAndKeepsAnExistingOutput) {
  const std::string dir = test::make_temp_dir("export-bad");
  const std::string bad = dir + "/bad.json", out = dir + "/out.bvh";
  write_file_atomically(bad, "{\"format\": \"fapcast-fap-json\", \"version\": 1");
  write_file_atomically(out, "previous");
  const auto r = run_command(fapcast("export '" + bad + "' -o '" + out + "'"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(bad + ": byte"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("json-syntax"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(out), "previous");
  fs::remove_all(dir);
}

TEST(ExportCli, HelpNamesBothFormats) {
  const auto r = run_command(fapcast("export --help"));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find(".bvh"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--sample-rate"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace fapcast
