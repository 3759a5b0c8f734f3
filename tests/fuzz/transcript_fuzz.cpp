// Fuzzes a transcript file's reading (decode_text, then parse_transcript): any input either gives
// words that are the input's own bytes at their offsets, or throws InputError; never crashes.
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/text_input.hpp"
#include "fapcast/recognise/transcript.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const std::string text =
        fapcast::decode_text(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz", "transcript");
    const fapcast::Transcript t = fapcast::parse_transcript(text, "fuzz");
    if (t.words.empty()) std::abort();
    std::size_t end = 0;
    for (const auto& w : t.words) {
      if (w.text.empty() || w.byte_offset < end || w.byte_offset + w.text.size() > t.text.size() ||
          t.text.compare(w.byte_offset, w.text.size(), w.text) != 0 || w.key.size() != w.text.size())
        std::abort();
      end = w.byte_offset + w.text.size();
    }
  } catch (const fapcast::InputError&) {
  }
  return 0;
}
