// Fuzzes the symbol mappers (IPA, IPA features, espeak-ng, TIMIT, ARPAbet), the text validator,
// the long-text chunker and the Festival lexicon and word-count parsers: any input either parses
// or throws std::invalid_argument (mappers) or InputError (parsers); nothing else may happen.
// The chunker's cuts must be increasing, within the limit and on code point boundaries.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "fapcast/core/input_error.hpp"
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/phonetics/ipa_features.hpp"
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
  expect_parse_or_invalid([&] { phone_from_ipa_features(text, "fuzz"); });
  expect_parse_or_invalid([&] { phone_from_espeak(text, "fuzz"); });
  expect_parse_or_invalid([&] { phone_from_timit(text, "fuzz"); });
  expect_parse_or_invalid([&] { parse_arpabet(text, "fuzz"); });
  expect_parse_or_invalid([&] { validate_text(text); });
  expect_parse_or_invalid([&] { parse_festival_lexicon(text, "fuzz"); });
  expect_parse_or_invalid([&] { parse_word_counts(text, "fuzz"); });
  const std::size_t limit = 4 + size % 61;
  const std::vector<std::size_t> starts = chunk_offsets(text, limit);
  bool valid = true;
  try {
    validate_text(text);
  } catch (const InputError&) {
    valid = false;
  }
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const std::size_t end = i + 1 < starts.size() ? starts[i + 1] : text.size();
    if ((i == 0) != (starts[i] == 0) || end <= starts[i] || end - starts[i] > limit) std::abort();
    if (valid && (data[starts[i]] & 0xC0) == 0x80) std::abort();  // inside a code point
  }
  if (starts.empty() != text.empty()) std::abort();
  return 0;
}
