// `fapcast voice build`, `voice info` and `eval retarget` end to end on a small SYNTHETIC
// reference corpus, and their refusals of bad input.
#include "support/bad_inputs.hpp"
#include "support/corpus_conversion.hpp"
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "fapcast/voice/voice.hpp"
#include "fapcast/core/file_io.hpp"

namespace fapcast::test {
namespace {

namespace fs = std::filesystem;

class VoiceCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(make_temp_dir("voice-cli"));
    const auto r = run_command(fapcast("corpus record-reference -q --count 40 --seed 1 -o " + corpus()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto b = run_command("SOURCE_DATE_EPOCH=1700000000 " + fapcast("voice build " + corpus() + " -o " + voice()));
    ASSERT_EQ(b.exit_code, 0) << b.err;
    *build_out_ = b.out;
    *build_err_ = b.err;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static std::string corpus() { return *dir_ + "/corpus"; }
  static std::string voice() { return *dir_ + "/reference.fapv"; }
  static std::string* dir_;
  static std::string* build_out_;
  static std::string* build_err_;
};
std::string* VoiceCli::dir_ = nullptr;
std::string* VoiceCli::build_out_ = new std::string;
std::string* VoiceCli::build_err_ = new std::string;

// Each test of this fixture records 40 script items and builds their voice (one process per
// test under CTest), so the fixture has three tests only.
TEST_F(VoiceCli, BuildShowsProgressAndInfoPrintsProvenanceAndSections) {
  EXPECT_NE(build_out_->find("2313 frames"), std::string::npos) << *build_out_;
  // all 21 classes: the first 40 items say an /l/ ("all") since the front end keeps it
  EXPECT_NE(build_out_->find("21 prototypes (target rank 18)"), std::string::npos) << *build_out_;
  EXPECT_NE(build_out_->find(" frames closed further"), std::string::npos) << *build_out_;
  EXPECT_NE(build_err_->find("voice build: read 40 / 40"), std::string::npos) << *build_err_;
  EXPECT_NE(build_err_->find("voice build: write"), std::string::npos) << *build_err_;
  const auto r = run_command(fapcast("voice info " + voice()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* want : {"synthetic:    yes", "SYNTHETIC", "2023-11-14T22:13:20Z", "prototype_rule", "lambda",
                           "r_squared_m2", "PCOM", "FCOE", "GRPH", "FPNT", "feature points 34", "k 17",
                           "LCSH", "LCON", "lip contact:  source "})
    EXPECT_NE(r.out.find(want), std::string::npos) << want << "\n" << r.out;
}

TEST_F(VoiceCli, SameCorpusAndEpochGiveTheSameBytes) {
  const std::string again = *dir_ + "/again.fapv";
  const auto r = run_command("SOURCE_DATE_EPOCH=1700000000 " + fapcast("voice build -q " + corpus() + " -o " + again));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;  // -q
  EXPECT_EQ(slurp(again), slurp(voice()));
  // The same takes as TRC markers with .lab alignments (listed by manifest.json, which keeps the
  // SYNTHETIC mark neither format carries): the same voice but for the provenance's corpus path.
  const std::string trc = *dir_ + "/trc-lab";
  convert_corpus(corpus(), trc, MarkerFormat::trc, AlignmentFormat::lab);
  const auto t = run_command(fapcast("voice build -q " + trc + " -o " + *dir_ + "/trc.fapv"));
  ASSERT_EQ(t.exit_code, 0) << t.err;
  const Voice from_c3d = Voice::open(voice());
  const Voice from_trc = Voice::open(*dir_ + "/trc.fapv");
  EXPECT_EQ(from_trc.frame_coefficients(), from_c3d.frame_coefficients());
  EXPECT_EQ(from_trc.pca_components(), from_c3d.pca_components());
  EXPECT_EQ(from_trc.graph().size(), from_c3d.graph().size());
  EXPECT_TRUE(from_trc.provenance().synthetic);
}

TEST_F(VoiceCli, EvalRetargetPrintsTheLipMeasures) {
  for (const std::string& extra : {std::string(), " --corpus " + corpus()}) {
    const auto r = run_command(fapcast("eval retarget -q " + voice() + extra));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* want : {"SYNTHETIC", "lip height", "lip width", "lip protrusion", "5.207", "40 utterances"})
      EXPECT_NE(r.out.find(want), std::string::npos) << want << "\n" << r.out;
  }
  const std::string empty = make_temp_dir("voice-cli-eval-empty");
  const auto r = run_command(fapcast("eval retarget -q " + voice() + " --corpus " + empty));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("corpus-empty"), std::string::npos) << r.err;
  fs::remove_all(empty);
}

TEST(VoiceCliBadInput, ExitsOneAndNamesTheProblem) {
  const std::string dir = make_temp_dir("voice-cli-bad");
  auto r = run_command(fapcast("voice build -q " + dir + "/missing -o " + dir + "/x.fapv"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("corpus-missing"), std::string::npos) << r.err;
  r = run_command(fapcast("voice build -q " + dir + " -o " + dir + "/x.fapv"));  // empty directory
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("corpus-empty"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/x.fapv"));
  // One stem, two marker formats: refused naming both files (tests/data/corpus/bad-corpora).
  const std::string ambiguous = std::string(FAPCAST_TEST_DATA) + "/corpus/bad-corpora/bad.001.corpus-ambiguous";
  r = run_command(fapcast("voice build -q " + ambiguous + " -o " + dir + "/x.fapv"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("u1.c3d: corpus-ambiguous: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("u1.c3d and u1.trc"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/x.fapv"));
  // A truncated voice (the container's named example) and a missing one.
  const std::string cut = std::string(FAPCAST_TEST_DATA) + "/voice/bad/bad.005.truncated.fapv";
  for (const std::string& cmd : {"voice info " + cut, "eval retarget " + cut}) {
    r = run_command(fapcast(cmd));
    EXPECT_EQ(r.exit_code, 1) << cmd;
    EXPECT_NE(r.err.find("bad.005.truncated.fapv: byte "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(": truncated: "), std::string::npos) << r.err;
  }
  r = run_command(fapcast("voice info " + dir + "/none.fapv"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("none.fapv"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(VoiceCliUsage, MistakesExitTwo) {
  const std::string corpus = std::string(FAPCAST_TEST_DATA) + "/voice";
  EXPECT_EQ(run_command(fapcast("voice build " + corpus)).exit_code, 2);  // no -o
  EXPECT_EQ(run_command(fapcast("voice build " + corpus + " -o x.fapv --pca fast")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("voice info")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("eval retarget")).exit_code, 2);
}

}  // namespace
}  // namespace fapcast::test
