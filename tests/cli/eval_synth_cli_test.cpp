// `fapcast eval synth`: its refusals of bad input and bad usage. (The run itself needs a voice
// covering every viseme class - the full default voice, minutes to build - so it is tested at the
// library level: tests/eval/synthesis_evaluation_test.cpp, tests/eval/synthesis_report_test.cpp.)
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace fapcast::test {
namespace {

TEST(EvalSynthCli, BadVoicesExitOneAndNameTheFile) {
  const std::string cut = std::string(FAPCAST_TEST_DATA) + "/voice/bad/bad.005.truncated.fapv";
  auto r = run_command(fapcast("eval synth -q --count 1 " + cut));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.005.truncated.fapv: byte "), std::string::npos) << r.err;
  const std::string dir = make_temp_dir("eval-synth-cli");
  r = run_command(fapcast("eval synth -q --count 1 " + dir + "/none.fapv --json-out " + dir + "/out.json"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("none.fapv"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.json")) << "nothing written on failure";
  std::filesystem::remove_all(dir);
}

TEST(EvalSynthCli, UsageMistakesExitTwo) {
  const std::string voice = std::string(FAPCAST_TEST_DATA) + "/voice/bad/bad.005.truncated.fapv";
  for (const char* args : {"--count 0", "--count 21", "--beta -1", "--duration-weight -0.5", "--jaw-weight -1",
                           "--jaw-cutoff 30", "--jaw-cutoff 0", "--jaw-level 1.5", "--jaw-level -1", "--seed x", "--bogus",
                           "--voice v.fapv", "--json out.json"}) {  // the voice is positional, outputs end in -out
    const auto r = run_command(fapcast("eval synth -q " + voice + " " + std::string(args)));
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
  }
  const auto help = run_command(fapcast("eval synth --help"));
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("SYNTHETIC"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("--plots-out"), std::string::npos) << help.out;
}

}  // namespace
}  // namespace fapcast::test
