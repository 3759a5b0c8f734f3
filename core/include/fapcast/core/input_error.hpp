#pragma once
// The error every reader throws for bad input (.fap, FBA, BVH, JSON, glTF, TextGrid, .lab, C3D,
// TRC, marker CSV, OBJ, TSV tables, voice files, text ...): where (source, line or byte offset)
// and which rule was broken, so that a message reads "joy.fap:12: mask-token-count: ..." or
// "take01.c3d: byte 512: c3d-...: ...".
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace fapcast {

struct InputLocation {
  std::string source;                   // file name, or "<memory>"
  std::optional<std::uint64_t> line;    // 1-based, for text formats
  std::optional<std::uint64_t> offset;  // 0-based byte offset, for binary formats
};

// `text` with every byte that is neither printable ASCII nor part of well-formed UTF-8 written
// as \xNN (control characters, stray bytes), so a message never echoes raw garbage to a terminal.
// InputError applies it to every detail.
std::string escape_for_message(std::string_view text);

class InputError : public std::runtime_error {
 public:
  // `rule` is a short stable identifier (kebab-case) that tests and golden files match on.
  InputError(InputLocation where, std::string rule, const std::string& detail);

  // A data file's error (meshes, targets, spec tables) at `line`, where line 0 means the file as
  // a whole: "file:line: rule: detail", or "file: rule: detail".
  static InputError in_file(std::string file, std::uint64_t line, std::string rule, const std::string& detail);

  const InputLocation& where() const { return where_; }
  // The 1-based line, or 0 when the error is not at a line.
  std::uint64_t line() const { return where_.line.value_or(0); }
  const std::string& rule() const { return rule_; }

 private:
  InputLocation where_;
  std::string rule_;
};

}  // namespace fapcast
