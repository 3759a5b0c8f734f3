#include "fapcast/synth/data_file_error.hpp"

#include <utility>

namespace fapcast::synth {

DataFileError::DataFileError(std::string file, std::size_t line, std::string rule,
                             const std::string& detail)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " + rule + ": " + detail),
      file_(std::move(file)),
      line_(line),
      rule_(std::move(rule)) {}

}  // namespace fapcast::synth
