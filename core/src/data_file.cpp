#include "fapcast/core/data_file.hpp"

#include <cmath>

#include "fapcast/core/input_error.hpp"

namespace fapcast {

std::ifstream open_data_file(const std::filesystem::path& file, std::uintmax_t max_bytes) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw InputError::in_file(file.string(), 0, "file-unreadable", ec.message());
  if (size > max_bytes)
    throw InputError::in_file(file.string(), 0, "file-too-large",
                        std::to_string(size) + " bytes (limit " + std::to_string(max_bytes) + ")");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError::in_file(file.string(), 0, "file-unreadable", "cannot open");
  return in;
}

bool next_content_line(std::istream& in, std::string& line, std::size_t& line_number) {
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line[first] != '#') return true;
  }
  return false;
}

float parse_coordinate(const std::filesystem::path& file, std::size_t line, std::string_view text) {
  float v = 0;
  if (!parse_number(text, v) || !std::isfinite(v))
    throw InputError::in_file(file.string(), line, "bad-coordinate", "'" + std::string(text) + "'");
  return v;
}

}  // namespace fapcast
