// Fuzzes the TextGrid reader; what it accepts must survive write -> read unchanged (both forms).
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/textgrid.hpp"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  Alignment grid;
  try {
    grid = read_textgrid(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const InputError&) {
    return 0;
  }
  for (TextGridForm form : {TextGridForm::long_form, TextGridForm::short_form}) {
    if (!(read_textgrid(write_textgrid(grid, form), "again") == grid)) std::abort();
  }
  return 0;
}
