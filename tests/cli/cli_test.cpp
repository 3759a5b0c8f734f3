// The command line's contract (spec/cli.md): --help lists the commands in pipeline order and
// --version the version; the synthesis options' defaults are the library's in every command that
// synthesises; exit 0 ok, 1 bad input, 2 bad usage (70, an internal error: exit_status_test.cpp).
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

#include "fapcast/synthesis/synthesis.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace fapcast::test {
namespace {

// The sub-command names under "Subcommands:" in CLI11's help text, in order.
std::vector<std::string> listed_commands(const std::string& help) {
  std::vector<std::string> names;
  std::istringstream lines(help);
  std::string line;
  bool in_list = false;
  while (std::getline(lines, line)) {
    if (line.rfind("Subcommands:", 0) == 0) {
      in_list = true;
    } else if (in_list && line.rfind("  ", 0) == 0 && line.size() > 2 && line[2] != ' ') {
      names.push_back(line.substr(2, line.find(' ', 2) - 2));
    } else if (in_list && line.empty() && !names.empty()) {
      break;
    }
  }
  return names;
}

// The default CLI11 shows for `option` ("--beta FLOAT:FLOAT in [0 - 1e+06]=0.1" gives "0.1").
std::string shown_default(const std::string& help, const std::string& option) {
  const auto at = help.find("  " + option + " ");
  if (at == std::string::npos) return "(no " + option + ")";
  const auto end = help.find('\n', at);
  const std::string line = help.substr(at, end - at);
  const auto eq = line.find('=');
  if (eq == std::string::npos) return "(no default)";
  return line.substr(eq + 1, line.find_first_of(" \t", eq) - eq - 1);
}

TEST(Cli, HelpListsTheCommandsInPipelineOrder) {
  const auto r = run_command(fapcast("--help"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(listed_commands(r.out),
            (std::vector<std::string>{"corpus", "align", "voice", "say", "animate", "eval", "adapt", "expressions", "fap",
                                      "encode", "decode", "export", "render", "stream", "recv", "serve"}))
      << r.out;
  EXPECT_EQ(listed_commands(run_command(fapcast("corpus --help")).out),
            (std::vector<std::string>{"script", "record-reference"}));
  EXPECT_EQ(listed_commands(run_command(fapcast("voice --help")).out),
            (std::vector<std::string>{"build", "info", "default", "adapt"}));
  EXPECT_EQ(listed_commands(run_command(fapcast("eval --help")).out),
            (std::vector<std::string>{"retarget", "synth", "align", "articulography"}));
}

TEST(Cli, VersionPrintsTheProjectVersion) {
  const auto r = run_command(fapcast("--version"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fapcast " FAPCAST_PROJECT_VERSION), std::string::npos) << r.out;
}

// What `eval synth` scores is what `say` and `animate` ship: one set of defaults, the library's.
TEST(Cli, SynthesisDefaultsAreTheLibrarysInEveryCommand) {
  const SynthesisOptions shipped;
  ASSERT_TRUE(shipped.search.max_active.has_value());
  for (const std::string command : {"say", "animate", "eval synth", "eval articulography"}) {
    SCOPED_TRACE(command);
    const auto r = run_command(fapcast(command + " --help"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(std::stod(shown_default(r.out, "--beta")), shipped.search.beta) << r.out;
    EXPECT_EQ(shown_default(r.out, "--max-active"), std::to_string(*shipped.search.max_active)) << r.out;
    EXPECT_EQ(std::stod(shown_default(r.out, "--duration-weight")), shipped.search.duration_weight) << r.out;
    EXPECT_EQ(std::stod(shown_default(r.out, "--jaw-weight")), shipped.search.jaw_weight) << r.out;
    EXPECT_EQ(std::stod(shown_default(r.out, "--jaw-cutoff")), shipped.jaw_cutoff_hz) << r.out;
    EXPECT_NE(r.out.find("--boundary-joins"), std::string::npos) << r.out;
  }
  EXPECT_EQ(shipped.search.beta, 0.1);  // spec/cli.md, spec/search.md
  EXPECT_EQ(*shipped.search.max_active, 64u);
  EXPECT_EQ(shipped.search.jaw_weight, 0.0);  // the jaw term is opt-in (spec/search.md)
  EXPECT_TRUE(shipped.concatenation.join_mid_phone);
}

TEST(Cli, BadInputExitsOneNamingFileLineAndRule) {
  const std::string bad = std::string(FAPCAST_TEST_DATA) + "/fap/bad/bad.009.truncated.fap";
  const auto r = run_command(fapcast("fap info '" + bad + "'"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("fapcast: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("bad.009.truncated.fap:4: truncated:"), std::string::npos) << r.err;
  // A file that cannot be opened is the input's fault too, not a bug.
  const auto missing = run_command(fapcast("decode /nonexistent/in.fba -o /tmp/x.fap"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("/nonexistent/in.fba"), std::string::npos) << missing.err;
  EXPECT_EQ(missing.err.find("internal error"), std::string::npos) << missing.err;
}

TEST(Cli, UnknownCommandOrNoCommandIsAUsageError) {
  EXPECT_EQ(run_command(fapcast("no-such-command")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("voice retarget v.fapv g.obj s.obj -o x.fapv")).exit_code, 2);  // it is `voice adapt`
}

}  // namespace
}  // namespace fapcast::test
