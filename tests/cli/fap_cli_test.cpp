// `fapcast fap info` and `fapcast fap convert` end to end: exit codes, messages, JSON, and
// atomic output (a failing convert leaves no file and never destroys an existing one).
#include "fapcast/codec/fap_text.hpp"
#include "fapcast/core/file_io.hpp"
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace fapcast {
namespace {

namespace fs = std::filesystem;
using test::fapcast;
using test::run_command;

const std::string kData = FAPCAST_TEST_DATA;
const std::string kJoy = kData + "/xface/joy.fap";

TEST(FapCli, InfoPrintsTheSummary) {
  const auto r = run_command(fapcast("fap info '" + kJoy + "'"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fap-text 2.1 (68-token masks, CRLF)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fps:       25 (exactly 25/1)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frames:    108 (header: 108)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("duration:  4.320 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("    3  open_jaw                    108       -6      315"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.err, "");
}

TEST(FapCli, InfoJsonIsMachineReadable) {
  const auto r = run_command(fapcast("fap info --json '" + kJoy + "'"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["version"], "2.1");
  EXPECT_EQ(j["frames"], 108);
  EXPECT_EQ(j["duration_ms"], 4320);
  EXPECT_EQ(j["rate"]["numerator"], 25);
  EXPECT_EQ(j["faps"].size(), 42u);
  EXPECT_EQ(j["faps"][0]["name"], "open_jaw");
  EXPECT_EQ(j["faps"][0]["min"], -6);
  EXPECT_TRUE(j["warnings"].empty());
}

TEST(FapCli, WarningsGoToStderr) {
  const std::string dir = test::make_temp_dir("fapcli");
  std::string mask = "0 0 1";  // open_jaw only
  for (int i = 0; i < 65; ++i) mask += " 0";
  write_file_atomically(dir + "/real.fap", "2.1 r 25 1\n" + mask + "\n0 3.6\n");
  const auto r = run_command(fapcast("fap info '" + dir + "/real.fap'"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("fapcast: warning: " + dir + "/real.fap:3: real-value: '3.6' rounded to 4"),
            std::string::npos) << r.err;
  EXPECT_NE(r.out.find("real-valued tokens"), std::string::npos) << r.out;
}

TEST(FapCli, InfoJsonCopesWithNamesAndPathsThatAreNotUtf8) {
  const std::string dir = test::make_temp_dir("fapcli");
  const std::string path = dir + "/caf\xE9.fap";
  write_file_atomically(path, "2.1 caf\xE9 25 0\n");
  const auto r = run_command(fapcast("fap info --json '" + path + "'"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["name"], "caf\xEF\xBF\xBD");
  EXPECT_EQ(j["frames"], 0);
  EXPECT_EQ(j["warnings"].size(), 1u);
}

TEST(FapCli, BadInputExitsOneWithFileLineRule) {
  const std::string bad = kData + "/fap/bad/bad.003.value-count.fap";
  const auto r = run_command(fapcast("fap info '" + bad + "'"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "fapcast: error: " + bad +
                       ":5: value-count: 2 tokens where the mask at line 4 asks for 3 (frame number + values)\n");
  EXPECT_EQ(run_command(fapcast("fap info /nonexistent/x.fap")).exit_code, 1);
}

TEST(FapCli, BadUsageExitsTwo) {
  EXPECT_EQ(run_command(fapcast("fap info")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("fap")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("fap convert '" + kJoy + "'")).exit_code, 2);  // no -o
  EXPECT_EQ(run_command(fapcast("fap convert '" + kJoy + "' /tmp/x.fap")).exit_code, 2);  // the output is -o
  EXPECT_EQ(run_command(fapcast("fap convert '" + kJoy + "' -o /tmp/x.fap --dialect 70")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("fap info --help")).exit_code, 0);
  EXPECT_EQ(run_command(fapcast("fap convert --help")).exit_code, 0);
}

TEST(FapCli, ConvertWritesBothDialectsThatReadBackTheSame) {
  const std::string dir = test::make_temp_dir("fapcli");
  const auto original = read_fap_text(read_file(kJoy), "joy.fap").sequence;
  for (const std::string dialect : {"strict", "69"}) {
    const std::string out = dir + "/joy-" + dialect + ".fap";
    const auto r = run_command(fapcast("fap convert '" + kJoy + "' -o '" + out + "' --dialect " + dialect));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto back = read_fap_text(read_file(out), out);
    EXPECT_EQ(back.sequence.frames, original.frames);
    EXPECT_EQ(back.info.dialect,
              dialect == "69" ? FapTextDialect::kMask69 : FapTextDialect::kStrict);
    EXPECT_FALSE(back.info.crlf);
  }
  // Only the two outputs: no temporary files left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 2);
}

TEST(FapCli, FailingConvertLeavesNoFileAndKeepsAnExistingOne) {
  const std::string dir = test::make_temp_dir("fapcli");
  const std::string bad = kData + "/fap/bad/bad.009.truncated.fap";
  auto r = run_command(fapcast("fap convert '" + bad + "' -o '" + dir + "/new.fap'"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(":4: truncated:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/new.fap"));

  write_file_atomically(dir + "/old.fap", "precious");
  r = run_command(fapcast("fap convert '" + bad + "' -o '" + dir + "/old.fap'"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(read_file(dir + "/old.fap"), "precious");
  // An unwritable destination is bad input too, and leaves nothing behind.
  r = run_command(fapcast("fap convert '" + kJoy + "' -o '" + dir + "/missing-dir/x.fap'"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
}

TEST(FapCli, ConvertTo69WarnsWhenItDropsVisemeFields) {
  const std::string dir = test::make_temp_dir("fapcli");
  std::string mask = "1 0";
  for (int i = 0; i < 66; ++i) mask += " 0";
  write_file_atomically(dir + "/v.fap", "2.1 v 25 1\n" + mask + "\n0 3 5 20 0\n");
  const auto r = run_command(fapcast("fap convert '" + dir + "/v.fap' -o '" + dir + "/v69.fap' --dialect 69"));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("1 frames have FAP 1/2 fields the 69-token dialect cannot carry"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace fapcast
