// Fuzzes a transcript file's reading (decode_text, then parse_transcript): any input either gives
// words that are the input's own bytes at their offsets (keys of their length, a typographic
// apostrophe as '), or throws InputError; never crashes.
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"
#include "fapcast/recognise/transcript.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {
// The dictionary key's length: the word's, less two bytes for each typographic apostrophe (U+2019,
// three bytes) that the key writes as '.
std::size_t key_size(std::string_view word) {
  std::size_t n = word.size();
  for (std::size_t at = word.find("\u2019"); at != std::string_view::npos; at = word.find("\u2019", at + 3)) n -= 2;
  return n;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const std::string text =
        fapcast::decode_text(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz", "transcript");
    const fapcast::Transcript t = fapcast::parse_transcript(text, "fuzz");
    if (t.words.empty()) std::abort();
    std::size_t end = 0;
    for (const auto& w : t.words) {
      if (w.text.empty() || w.byte_offset < end || w.byte_offset + w.text.size() > t.text.size() ||
          t.text.compare(w.byte_offset, w.text.size(), w.text) != 0 || w.key.size() != key_size(w.text))
        std::abort();
      end = w.byte_offset + w.text.size();
    }
  } catch (const fapcast::InputError&) {
  }
  return 0;
}
