// `fapcast corpus script` end to end, on small fixtures and on a bad lexicon.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

namespace {

using fapcast::test::fapcast;
using fapcast::test::run_command;

const std::string kData = FAPCAST_TEST_DATA "/lexicon/";

TEST(CorpusScriptCommand, WritesScriptAndPrintsCoverage) {
  const std::string dir = fapcast::test::make_temp_dir("corpus_script");
  const auto r = run_command(fapcast("corpus script --cmudict " + kData + "mini-cmudict.out --word-counts " +
                                     kData + "mini-word-counts.tsv --common 2 --syllable-words 3 -o " + dir +
                                     "/script.tsv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("# divisemes covered in total: 440 of 440 (100.00 %)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("# uncovered divisemes: none"), std::string::npos);
  std::ifstream in(dir + "/script.tsv");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("common\t1\tyou\tY UW1\t\n"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("\nnonsense\t1\t"), std::string::npos);
}

// Defaults: the vendored SUBTLEX-US counts (data/lexicon) and festlex-cmu; the paper's sizes.
TEST(CorpusScriptCommand, DefaultDataGivesFullDivisemeCoverage) {
  if (!std::filesystem::exists("/usr/share/festival/dicts/cmu/cmudict-0.4.out")) GTEST_SKIP() << "festlex-cmu missing";
  const auto r = run_command("env -u FAPCAST_DATA -u FAPCAST_CMUDICT " + fapcast("corpus script"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("# sections: common 100, syllable 800, nonsense "), std::string::npos) << r.out.substr(0, 400);
  EXPECT_NE(r.out.find("# uncovered divisemes: none"), std::string::npos);
  EXPECT_NE(r.out.find("\ncommon\t1\tyou\t"), std::string::npos);
}

TEST(CorpusScriptCommand, BadLexiconNamesFileLineAndRule) {
  const auto r = run_command(fapcast("corpus script --cmudict " + kData + "bad/bad.004.bad-stress.out --word-counts " +
                                     kData + "mini-word-counts.tsv"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.004.bad-stress.out:1: bad-stress: stress '3' is not 0, 1 or 2"), std::string::npos)
      << r.err;
}

}  // namespace
