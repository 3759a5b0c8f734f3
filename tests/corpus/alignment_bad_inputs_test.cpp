// Every named bad alignment file (tests/data/alignment/bad, written by make_bad_alignments.py)
// is refused through read_alignment_file with the rule its name carries and exactly the message
// in expected-errors.txt; options.tsv says with which recording rate, length and tier.
#include "fapcast/corpus/alignment_file.hpp"
#include "fapcast/core/input_error.hpp"
#include "support/bad_inputs.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fapcast {
namespace {

namespace fs = std::filesystem;
const fs::path kBad = fs::path(FAPCAST_TEST_DATA) / "alignment" / "bad";

struct BadCase {
  std::string name;
  AlignmentFileOptions options;
};

std::vector<BadCase> bad_cases() {
  std::vector<BadCase> cases;
  std::istringstream lines(test::slurp(kBad / "options.tsv"));
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    std::string name, rate, audio, tier;
    std::getline(f, name, '\t');
    std::getline(f, rate, '\t');
    std::getline(f, audio, '\t');
    std::getline(f, tier, '\t');
    BadCase c{name, {}};
    if (rate != "-") c.options.sample_rate = SampleRate{std::stoll(rate)};
    if (audio != "-") c.options.audio_seconds = std::stod(audio);
    if (tier != "-") c.options.tier = tier;
    cases.push_back(std::move(c));
  }
  return cases;
}

TEST(AlignmentBadInputs, EachIsRefusedWithItsRuleAndGoldenMessage) {
  const auto golden = std::getenv("FAPCAST_REGENERATE") ? std::map<std::string, std::string>{} : test::golden_errors(kBad);
  const auto cases = bad_cases();
  ASSERT_GE(cases.size(), 50u);
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(kBad)) files += e.path().filename().string().starts_with("bad.");
  EXPECT_EQ(files, cases.size()) << "options.tsv and the bad files disagree: rerun make_bad_alignments.py";
  std::string regenerated;
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.name);
    std::string message = "read";
    try {
      (void)read_alignment_file(test::slurp(kBad / c.name), c.name, c.options);
    } catch (const InputError& e) {
      message = e.what();
      EXPECT_EQ(e.rule(), test::rule_of(c.name));
    }
    regenerated += message + "\n";
    if (std::getenv("FAPCAST_REGENERATE")) continue;
    const auto g = golden.find(c.name);
    if (g == golden.end()) {
      ADD_FAILURE() << "no golden line";
      continue;
    }
    EXPECT_EQ(message, g->second);
  }
  if (std::getenv("FAPCAST_REGENERATE")) {
    std::ofstream(kBad / "expected-errors.txt", std::ios::binary) << regenerated;  // review with git diff
  } else if (HasFailure()) {
    std::cout << "messages now (FAPCAST_REGENERATE=1 writes them):\n" << regenerated;
  }
}

}  // namespace
}  // namespace fapcast
