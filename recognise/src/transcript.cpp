#include "fapcast/recognise/transcript.hpp"

#include <optional>
#include <string>

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/utf8.hpp"
#include "fapcast/frontend/text_frontend.hpp"

namespace fapcast {

namespace {

// The detail of an InputError's message: what follows "RULE: ".
std::string detail_of(const InputError& e) {
  const std::string what = e.what(), marker = e.rule() + ": ";
  const auto at = what.find(marker);
  return at == std::string::npos ? what : what.substr(at + marker.size());
}

bool ascii_alnum(char32_t c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// Punctuation and spaces outside ASCII (no-break space, « », dashes, curly quotes, ellipsis, CJK
// and full-width punctuation) separate words like ASCII punctuation does.
bool separates_words(char32_t c) {
  return c < 0x80 ? !ascii_alnum(c)
                  : (c >= 0x00A0 && c <= 0x00BF) || c == 0x00D7 || c == 0x00F7 || (c >= 0x2000 && c <= 0x206F) ||
                        (c >= 0x2E00 && c <= 0x2E7F) || (c >= 0x3000 && c <= 0x303F) || (c >= 0xFF01 && c <= 0xFF0F) ||
                        (c >= 0xFF1A && c <= 0xFF20) || (c >= 0xFF3B && c <= 0xFF40) || (c >= 0xFF5B && c <= 0xFF65);
}

// An apostrophe, ASCII or the typographic U+2019.
bool is_apostrophe(char32_t c) { return c == '\'' || c == 0x2019; }

}  // namespace

Transcript parse_transcript(std::string_view text, const std::string& source) {
  try {
    validate_text(text);
  } catch (const InputError& e) {  // the front-end names its input "text": name the transcript
    throw InputError({source, std::nullopt, e.where().offset}, e.rule(), detail_of(e));
  }
  Transcript t;
  t.text = std::string(text);
  std::size_t i = 0;
  while (i < text.size()) {
    const Utf8CodePoint c = decode_utf8_at(text, i);  // valid: validate_text passed
    if (separates_words(c.value)) {
      i += c.bytes;
      continue;
    }
    std::size_t j = i;
    std::string key;
    while (j < text.size()) {
      const Utf8CodePoint next = decode_utf8_at(text, j);
      const char32_t d = next.value;
      const std::size_t m = next.bytes;
      if (separates_words(d)) {
        // an apostrophe inside a word ("don't", "don’t"), not at its end ("the boys' ")
        if (!is_apostrophe(d) || j + m >= text.size() || separates_words(decode_utf8_at(text, j + m).value)) break;
        key += '\'';
      } else if (d >= 'A' && d <= 'Z') {
        key += static_cast<char>(d - 'A' + 'a');
      } else {
        key.append(text.substr(j, m));
      }
      j += m;
    }
    t.words.push_back(TranscriptWord{std::string(text.substr(i, j - i)), std::move(key), i});
    i = j;
  }
  if (t.words.empty()) throw InputError({source, std::nullopt, std::nullopt}, "transcript-empty", "no word to align");
  return t;
}

}  // namespace fapcast
