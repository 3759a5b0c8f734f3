#pragma once
// The error every codec reader throws for bad input: where (source, line or byte offset) and
// which rule was broken, so that a message reads "joy.fap:12: mask-token-count: ...".
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace fapcast {

struct InputLocation {
  std::string source;                   // file name, or "<memory>"
  std::optional<std::uint64_t> line;    // 1-based, for text formats
  std::optional<std::uint64_t> offset;  // 0-based byte offset, for binary formats
};

class InputError : public std::runtime_error {
 public:
  // `rule` is a short stable identifier (kebab-case) that tests and golden files match on.
  InputError(InputLocation where, std::string rule, const std::string& detail);

  const InputLocation& where() const { return where_; }
  const std::string& rule() const { return rule_; }

 private:
  InputLocation where_;
  std::string rule_;
};

}  // namespace fapcast
