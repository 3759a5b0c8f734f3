#include "fapcast/core/input_error.hpp"

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

}  // namespace fapcast
