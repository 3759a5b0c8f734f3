#pragma once
// Named bad inputs (`bad/bad.NNN.<rule>.<ext>`) and their golden list of expected messages
// (`bad/expected-errors.txt`, one "name:...: rule: detail" line each), shared by reader tests.
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/file_bytes.hpp"

namespace fapcast::test {

// The file names in `dir` ending in `ext` (".bvh"), sorted.
inline std::vector<std::string> bad_input_names(const std::filesystem::path& dir,
                                                const std::string& ext) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ext) names.insert(e.path().filename().string());
  return {names.begin(), names.end()};
}

// The rule a bad input is named after: "bad.012.mask-count.fap" -> "mask-count".
inline std::string rule_of(const std::string& name) {
  const auto first = name.find('.', name.find('.') + 1) + 1;
  return name.substr(first, name.rfind('.') - first);
}

// expected-errors.txt in `dir`, keyed by file name (the text before the first ':').
inline std::map<std::string, std::string> golden_errors(const std::filesystem::path& dir) {
  std::map<std::string, std::string> golden;
  std::istringstream lines(slurp(dir / "expected-errors.txt"));
  for (std::string line; std::getline(lines, line);) golden[line.substr(0, line.find(':'))] = line;
  return golden;
}

// A golden list in `file`, keyed by the text before the first ": " (the file name); empty lines
// and '#' comment lines skipped (the voice files' EXPECTED.txt).
inline std::map<std::string, std::string> golden_lines(const std::filesystem::path& file) {
  std::map<std::string, std::string> golden;
  std::istringstream lines(slurp(file));
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line[0] != '#') golden[line.substr(0, line.find(": "))] = line;
  return golden;
}

// A GoogleTest parameter name for a file name: "bad.001.x-y.bvh" -> "bad_001_x_y".
inline std::string test_name_of(std::string name) {
  name = name.substr(0, name.rfind('.'));
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

}  // namespace fapcast::test
