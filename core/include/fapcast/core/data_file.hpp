#pragma once
// Line-oriented reading of data files (meshes, targets, spec tables), with size limits.
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace fapcast {

// Opens `file` for reading; throws InputError (line 0) when it is missing, unreadable or
// larger than max_bytes.
std::ifstream open_data_file(const std::filesystem::path& file, std::uintmax_t max_bytes);

// Reads the next line that is neither blank nor a '#' comment into `line` (CR stripped),
// counting every line read in `line_number`; false at the end of the stream.
bool next_content_line(std::istream& in, std::string& line, std::size_t& line_number);

// Parses all of `text` as a number of type T; false on any leftover, overflow or empty text.
template <typename T>
bool parse_number(std::string_view text, T& value) {
  const auto [end, err] = std::from_chars(text.data(), text.data() + text.size(), value);
  return err == std::errc{} && end == text.data() + text.size() && !text.empty();
}

// A finite float coordinate; throws InputError(file, line, "bad-coordinate") otherwise.
float parse_coordinate(const std::filesystem::path& file, std::size_t line, std::string_view text);

}  // namespace fapcast
