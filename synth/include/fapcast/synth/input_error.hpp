#pragma once
// The error every synth reader (TextGrid, .lab, C3D, TRC, marker CSV, phone maps, lexicons ...)
// throws for bad input: where (source, line or byte offset) and which rule was broken, so that a
// message reads "take01.TextGrid:12: interval-order: ..." or "take01.c3d: byte 512: c3d-...: ...".
// Same idea as codec's InputError; synth has its own because it must not include codec headers.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace fapcast::synth {

struct InputLocation {
  std::string source;                   // file name, or "<memory>" when empty
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

}  // namespace fapcast::synth
