#pragma once
// The error every synth data reader throws: which file, which line, which rule was broken.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace fapcast::synth {

// "file:line: rule-id: detail" (line 0 = the file as a whole).
class DataFileError : public std::runtime_error {
 public:
  DataFileError(std::string file, std::size_t line, std::string rule, const std::string& detail);
  const std::string& file() const noexcept { return file_; }
  std::size_t line() const noexcept { return line_; }
  const std::string& rule() const noexcept { return rule_; }

 private:
  std::string file_;
  std::size_t line_;
  std::string rule_;
};

}  // namespace fapcast::synth
