// `fapcast eval synth`: its refusals of bad input and bad usage. (The run itself needs a voice
// covering every viseme class - the full default voice, minutes to build - so it is tested at the
// library level: tests/eval/synthesis_evaluation_test.cpp, tests/eval/synthesis_report_test.cpp.)
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"
#include "support/tiny_voice.hpp"

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

// Held-out takes are spoken by the actor of the voice's own corpus: a voice that does not say which
// corpus it was built from is refused, not scored against another face.
TEST(EvalSynthCli, AVoiceOfNoKnownCorpusSeedExitsOne) {
  TinyVoice tiny;  // synthetic, no corpus_seed
  const std::string file = (std::filesystem::temp_directory_path() / "eval_synth_no_corpus_seed.fapv").string();
  write_file_atomically(file, tiny.bytes());
  const auto r = run_command(fapcast("eval synth -q --count 1 " + file));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("eval_synth_no_corpus_seed.fapv: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("corpus_seed"), std::string::npos) << r.err;
  std::filesystem::remove(file);
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
