// The command line's contract: --help and --version succeed, usage mistakes exit 2.
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

#include <gtest/gtest.h>

namespace fapcast::test {
namespace {

TEST(Cli, HelpListsCommandsAndExitsZero) {
  const auto r = run_command(fapcast("--help"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fapcast"), std::string::npos) << r.out;
}

TEST(Cli, VersionPrintsTheProjectVersion) {
  const auto r = run_command(fapcast("--version"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fapcast " FAPCAST_PROJECT_VERSION), std::string::npos) << r.out;
}

TEST(Cli, UnknownCommandOrNoCommandIsAUsageError) {
  EXPECT_EQ(run_command(fapcast("no-such-command")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("")).exit_code, 2);
}

}  // namespace
}  // namespace fapcast::test
