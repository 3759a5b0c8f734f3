#pragma once
// Tab-separated spec tables (spec/*.tsv): '#' comments, blank lines skipped, fixed column count.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

struct TsvRow {
  std::size_t line = 0;             // 1-based line number in the file
  std::vector<std::string> fields;  // exactly the table's column count
};

// Reads a TSV table with `columns` columns; throws InputError (file:line: rule) when a row
// has another count, the file is missing, or it exceeds 1 MiB.
std::vector<TsvRow> read_tsv(const std::filesystem::path& file, std::size_t columns);

// Parses a finite float field; throws InputError naming file, line and column.
float tsv_float(const std::filesystem::path& file, const TsvRow& row, std::size_t column);

// Parses an integer field in [low, high]; throws InputError naming file, line and column.
long long tsv_integer(const std::filesystem::path& file, const TsvRow& row, std::size_t column,
                      long long low, long long high);

}  // namespace fapcast
