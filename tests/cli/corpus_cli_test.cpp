// `fapcast corpus record-reference`: the same seed records the same corpus, byte for byte, in
// another process; another seed records another one; and the files say SYNTHETIC.
#include "support/bad_inputs.hpp"
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fapcast::test {
namespace {

using fapcast::test::slurp;

TEST(CorpusCli, RecordReferenceIsReproducibleFromItsSeed) {
  const std::string a = make_temp_dir("corpus-a"), b = make_temp_dir("corpus-b"), c = make_temp_dir("corpus-c");
  for (const auto& [dir, seed] : {std::pair{a, 4}, std::pair{b, 4}, std::pair{c, 5}}) {
    const auto r = run_command(fapcast("corpus record-reference -q --count 4 --seed " + std::to_string(seed) + " -o " + dir));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("SYNTHETIC"), std::string::npos) << r.out;
  }
  for (const char* name : {"manifest.json", "utt0001.c3d", "utt0003.TextGrid", "utt0004.wav"}) {
    EXPECT_EQ(slurp(std::filesystem::path(a) / name), slurp(std::filesystem::path(b) / name)) << name;
  }
  EXPECT_NE(slurp(std::filesystem::path(a) / "utt0001.c3d"), slurp(std::filesystem::path(c) / "utt0001.c3d"));
  EXPECT_NE(slurp(std::filesystem::path(a) / "utt0001.c3d").find("SYNTHETIC"), std::string::npos);
  EXPECT_NE(slurp(std::filesystem::path(a) / "utt0001.TextGrid").find("SYNTHETIC"), std::string::npos);
  for (const auto& d : {a, b, c}) std::filesystem::remove_all(d);
}

TEST(CorpusCli, RecordReferenceWithoutOutputIsAUsageError) {
  EXPECT_EQ(run_command(fapcast("corpus record-reference --count 1")).exit_code, 2);
}

}  // namespace
}  // namespace fapcast::test
