// `fapcast serve` refuses to start on a bad SRTP key file: exit 1, the file, byte and rule on
// standard error, nothing listening (no URL printed on standard output). (A bad token file:
// ServeCli.UsageAndBadInput.)
#include "fapcast/core/file_io.hpp"
#include "support/run_command.hpp"
#include "support/spoken_voice.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace fapcast {
namespace {

std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

test::CommandResult serve_with(const std::filesystem::path& token, const std::string& extra) {
  return test::run_command(q(FAPCAST_EXE) + " serve -q --listen 127.0.0.1:0 --token-file " + q(token) + " --voice " +
                           q(test::spoken_voice_file()) + " " + extra);
}

TEST(ServeCli, BadSrtpKeyFileExitsOneNamingFileByteAndRule) {
  const std::filesystem::path dir = test::make_temp_dir("serve_cli");
  write_file_atomically(dir / "token", "c2VjcmV0LXRva2VuLWZvci10ZXN0cw\n");
  const auto key = std::filesystem::path(FAPCAST_TEST_DATA) / "srtp" / "bad" / "bad.004.srtp-key-weak.key";
  const auto r = serve_with(dir / "token", "--srtp-key-file " + q(key));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(key.string() + ": byte 0: srtp-key-weak: every byte is the same"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

}  // namespace
}  // namespace fapcast
