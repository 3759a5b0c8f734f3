#include "fapcast/synth/input_error.hpp"

namespace fapcast::synth {
namespace {
// "file:12: rule: detail" for text formats, "file: byte 512: rule: detail" for binary ones.
std::string format(const InputLocation& at, const std::string& rule, const std::string& detail) {
  std::string s = at.source.empty() ? "<memory>" : at.source;
  if (at.line) s += ":" + std::to_string(*at.line);
  if (at.offset) s += ": byte " + std::to_string(*at.offset);
  return s + ": " + rule + ": " + detail;
}
}  // namespace

InputError::InputError(InputLocation where, std::string rule, const std::string& detail)
    : std::runtime_error(format(where, rule, detail)), where_(std::move(where)),
      rule_(std::move(rule)) {}

}  // namespace fapcast::synth
