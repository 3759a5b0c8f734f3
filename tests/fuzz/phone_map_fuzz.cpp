// Fuzzes the symbol mappers (IPA, espeak-ng, TIMIT, ARPAbet), the text validator, and the
// Festival lexicon and word-count parsers: any input either parses or throws
// std::invalid_argument (mappers) or InputError (parsers); nothing else may happen.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "fapcast/core/input_error.hpp"
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/phonetics/phone_map.hpp"
#include "fapcast/corpus/syllabified_lexicon.hpp"
#include "fapcast/frontend/text_frontend.hpp"

namespace {
template <class F>
void expect_parse_or_invalid(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument&) {  // symbol mappers
  } catch (const fapcast::InputError&) {  // text and file parsers
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapcast;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  expect_parse_or_invalid([&] { phones_from_ipa(text, "fuzz"); });
  expect_parse_or_invalid([&] { phone_from_espeak(text, "fuzz"); });
  expect_parse_or_invalid([&] { phone_from_timit(text, "fuzz"); });
  expect_parse_or_invalid([&] { parse_arpabet(text, "fuzz"); });
  expect_parse_or_invalid([&] { validate_text(text); });
  expect_parse_or_invalid([&] { parse_festival_lexicon(text, "fuzz"); });
  expect_parse_or_invalid([&] { parse_word_counts(text, "fuzz"); });
  return 0;
}
