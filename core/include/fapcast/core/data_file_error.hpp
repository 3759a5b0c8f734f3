#pragma once
// The InputError of synth's data-file readers (OBJ, sparse targets, TSV tables, JSON indices):
// built from a file and a line number, where line 0 means the file as a whole.
#include "fapcast/core/input_error.hpp"

#include <cstddef>
#include <string>

namespace fapcast {

class DataFileError : public InputError {
 public:
  DataFileError(std::string file, std::size_t line, std::string rule, const std::string& detail);
  std::size_t line() const noexcept { return static_cast<std::size_t>(where().line.value_or(0)); }
};

}  // namespace fapcast
