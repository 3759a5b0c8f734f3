#include "fapcast/core/tsv_table.hpp"

#include <charconv>
#include <cmath>

#include "fapcast/core/data_file.hpp"
#include "fapcast/core/input_error.hpp"

namespace fapcast {
namespace {

constexpr std::uintmax_t kMaxTsvBytes = 1u << 20;

std::vector<std::string> split_tabs(std::string_view line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const auto tab = line.find('\t', start);
    out.emplace_back(line.substr(start, tab == std::string_view::npos ? tab : tab - start));
    if (tab == std::string_view::npos) return out;
    start = tab + 1;
  }
}

}  // namespace

std::vector<TsvRow> read_tsv(const std::filesystem::path& file, std::size_t columns) {
  auto in = open_data_file(file, kMaxTsvBytes);
  std::vector<TsvRow> rows;
  std::string line;
  std::size_t number = 0;
  while (next_content_line(in, line, number)) {
    TsvRow row{number, split_tabs(line)};
    if (row.fields.size() != columns)
      throw InputError::in_file(file.string(), number, "column-count",
                          "expected " + std::to_string(columns) + " tab-separated fields, got " +
                              std::to_string(row.fields.size()));
    rows.push_back(std::move(row));
  }
  return rows;
}

float tsv_float(const std::filesystem::path& file, const TsvRow& row, std::size_t column) {
  const std::string& text = row.fields.at(column);
  float value = 0;
  const auto [end, err] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (err != std::errc{} || end != text.data() + text.size() || !std::isfinite(value))
    throw InputError::in_file(file.string(), row.line, "bad-number",
                        "column " + std::to_string(column + 1) + ": '" + text + "'");
  return value;
}

long long tsv_integer(const std::filesystem::path& file, const TsvRow& row, std::size_t column,
                      long long low, long long high) {
  const std::string& text = row.fields.at(column);
  long long value = 0;
  const auto [end, err] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (err != std::errc{} || end != text.data() + text.size())
    throw InputError::in_file(file.string(), row.line, "bad-integer",
                        "column " + std::to_string(column + 1) + ": '" + text + "'");
  if (value < low || value > high)
    throw InputError::in_file(file.string(), row.line, "out-of-range",
                        "column " + std::to_string(column + 1) + ": " + text + " not in [" +
                            std::to_string(low) + ", " + std::to_string(high) + "]");
  return value;
}

}  // namespace fapcast
