#include "fapcast/core/input_error.hpp"

#include <utility>

namespace fapcast {
namespace {
std::string format(const InputLocation& at, const std::string& rule, const std::string& detail) {
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on long operator+ chains at -O2.
  std::string s = at.source.empty() ? std::string("<memory>") : at.source;
  if (at.line) s.append(":").append(std::to_string(*at.line));
  if (at.offset) s.append(": byte ").append(std::to_string(*at.offset));
  s.append(": ").append(rule).append(": ").append(detail);
  return s;
}
}  // namespace

InputError::InputError(InputLocation where, std::string rule, const std::string& detail)
    : std::runtime_error(format(where, rule, detail)), where_(std::move(where)),
      rule_(std::move(rule)) {}

InputError InputError::in_file(std::string file, std::uint64_t line, std::string rule, const std::string& detail) {
  return InputError({std::move(file), line == 0 ? std::nullopt : std::optional<std::uint64_t>(line), std::nullopt},
                    std::move(rule), detail);
}

}  // namespace fapcast
