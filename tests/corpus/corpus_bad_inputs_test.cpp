// Every named bad input in tests/data/corpus/bad is refused with exactly the message listed in
// expected-errors.txt, and with the rule its file name carries (bad.NNN.<rule>.<ext>).
#include "fapcast/corpus/c3d.hpp"
#include "fapcast/corpus/ema.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/lab_file.hpp"
#include "fapcast/corpus/marker_csv.hpp"
#include "fapcast/corpus/textgrid.hpp"
#include "fapcast/corpus/trc.hpp"
#include "corpus/corpus_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace fapcast {
namespace {

namespace fs = std::filesystem;

// Reads `bytes` with the reader for the file's extension.
void read_by_extension(const std::string& bytes, const fs::path& name) {
  const std::string ext = name.extension().string();
  const std::string source = name.filename().string();
  if (ext == ".TextGrid") (void)read_textgrid(bytes, source);
  else if (ext == ".lab") (void)read_lab(bytes, source);
  else if (ext == ".c3d") (void)read_c3d(bytes, source);
  else if (ext == ".trc") (void)read_trc(bytes, source);
  else if (ext == ".csv") (void)read_marker_csv(bytes, source);
  else if (ext == ".ema") (void)read_ema(bytes, source);
  else throw std::logic_error("no reader for " + source);
}

std::map<std::string, std::string> golden() {
  std::map<std::string, std::string> expected;
  const std::string text = test::file_bytes(test::corpus_data() / "bad/expected-errors.txt");
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    if (line.empty() || line.starts_with('#')) continue;
    const std::size_t tab = line.find('\t');
    expected[line.substr(0, tab)] = line.substr(tab + 1);
  }
  return expected;
}

std::vector<fs::path> bad_files() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(test::corpus_data() / "bad")) {
    if (e.path().filename().string().starts_with("bad.")) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(CorpusBadInputs, EachFileFailsWithItsGoldenMessageAndRule) {
  const auto expected = golden();
  const auto files = bad_files();
  ASSERT_GE(files.size(), 30u);
  std::string regenerated;  // printed on mismatch, to paste into expected-errors.txt after review
  int mismatches = 0;
  for (const fs::path& path : files) {
    const std::string name = path.filename().string();
    const std::string rule = name.substr(8, name.size() - 8 - path.extension().string().size());
    try {
      read_by_extension(test::file_bytes(path), path);
      ADD_FAILURE() << name << " was accepted";
    } catch (const InputError& e) {
      regenerated += name + "\t" + e.what() + "\n";
      EXPECT_EQ(e.rule(), rule) << name;
      const auto it = expected.find(name);
      if (it == expected.end() || it->second != e.what()) {
        ++mismatches;
        ADD_FAILURE() << name << ": got \"" << e.what() << "\", golden \""
                      << (it == expected.end() ? "<none>" : it->second) << "\"";
      }
    }
  }
  EXPECT_EQ(expected.size(), files.size()) << "golden list and bad/ directory differ";
  if (mismatches > 0) std::cout << "---- regenerated list ----\n" << regenerated;
}

TEST(CorpusBadInputs, EnoughNamedInputsPerFormat) {
  std::map<std::string, int> per_extension;
  for (const fs::path& path : bad_files()) ++per_extension[path.extension().string()];
  EXPECT_GE(per_extension[".TextGrid"], 6);
  EXPECT_GE(per_extension[".c3d"], 6);
  EXPECT_GE(per_extension[".lab"], 3);
  EXPECT_GE(per_extension[".trc"], 3);
  EXPECT_GE(per_extension[".csv"], 3);
  EXPECT_GE(per_extension[".ema"], 16);  // text and binary: header, data and time rules
}

}  // namespace
}  // namespace fapcast
