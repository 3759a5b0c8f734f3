#pragma once
// What the text readers (TextGrid, .lab, TRC, marker CSV, OBJ, TSV tables) share: decoding to
// UTF-8, splitting into numbered lines and fields, strict number parsing with located errors.
#include "fapcast/core/input_error.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

// Throws InputError at `line` of `source` (text readers' single way to fail).
[[noreturn]] void fail_at_line(const std::string& source, std::uint64_t line, const std::string& rule,
                               const std::string& detail);

// The bytes as UTF-8: strips a UTF-8 BOM, converts UTF-16 LE/BE (BOM required) and checks that
// the result is valid UTF-8 with no NUL. Throws InputError with rule "<format>-encoding".
std::string decode_text(std::string_view bytes, const std::string& source, std::string_view format);

struct TextLine {
  std::string_view text;  // without the line terminator (\n, \r\n or \r)
  std::uint64_t number;   // 1-based
};

// The lines of `text`; a final terminator does not start an empty last line.
std::vector<TextLine> split_lines(std::string_view text);

// `text` cut at every `separator` (n separators give n + 1 fields).
std::vector<std::string_view> split_fields(std::string_view text, char separator);

// Splits on runs of spaces and tabs, ignoring leading and trailing ones.
std::vector<std::string_view> split_whitespace(std::string_view text);

// Without leading and trailing spaces, tabs.
std::string_view trim(std::string_view text);

// Whether `field` spells exactly one finite double (optional sign, decimal or exponent form);
// if so, stores it in `value`.
bool parse_finite(std::string_view field, double& value);

// Whether `field` spells exactly one decimal integer in [0, INT64_MAX]; if so, stores it.
bool parse_count(std::string_view field, std::int64_t& value);

// The shortest decimal that reads back to exactly `value` (std::to_chars).
std::string shortest_decimal(double value);

// `text` cut to at most 40 bytes for quoting in an error message, with "..." when cut.
std::string excerpt(std::string_view text);

}  // namespace fapcast
