// libFuzzer: any bytes as a spec table (spec/*.tsv) through read_tsv and its field parsers. The
// first byte picks the column count (1..12). Either InputError, or rows of exactly that many
// fields on increasing lines, each field either parsed or refused with InputError.
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/tsv_table.hpp"
#include "fuzz/support/scratch_file.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  if (size == 0) return 0;
  const std::size_t columns = 1 + data[0] % 12;
  const auto path = fuzz::scratch_file("table.tsv", {reinterpret_cast<const char*>(data + 1), size - 1});
  std::vector<TsvRow> rows;
  try {
    rows = read_tsv(path, columns);
  } catch (const InputError&) {
    return 0;
  }
  std::size_t last_line = 0;
  for (const TsvRow& row : rows) {
    if (row.fields.size() != columns || row.line <= last_line) std::abort();
    last_line = row.line;
    for (std::size_t c = 0; c < columns; ++c) {
      try {
        if (!std::isfinite(tsv_float(path, row, c))) std::abort();
      } catch (const InputError&) {
      }
      try {
        const long long v = tsv_integer(path, row, c, -1000, 1000);
        if (v < -1000 || v > 1000) std::abort();
      } catch (const InputError&) {
      }
    }
  }
  return 0;
}
