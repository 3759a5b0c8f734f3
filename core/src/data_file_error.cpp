#include "fapcast/core/data_file_error.hpp"

#include <optional>
#include <utility>

namespace fapcast {

DataFileError::DataFileError(std::string file, std::size_t line, std::string rule,
                             const std::string& detail)
    : InputError({std::move(file), line == 0 ? std::nullopt : std::optional<std::uint64_t>(line), std::nullopt},
                 std::move(rule), detail) {}

}  // namespace fapcast
