#include "fapcast/recognise/transcript.hpp"

#include <optional>
#include <string>

#include "fapcast/core/input_error.hpp"
#include "fapcast/frontend/text_frontend.hpp"

namespace fapcast {

namespace {

// The detail of an InputError's message: what follows "RULE: ".
std::string detail_of(const InputError& e) {
  const std::string what = e.what(), marker = e.rule() + ": ";
  const auto at = what.find(marker);
  return at == std::string::npos ? what : what.substr(at + marker.size());
}

bool ascii_alnum(unsigned char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

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
    const auto c = static_cast<unsigned char>(text[i]);
    if (!ascii_alnum(c) && c < 0x80) {
      ++i;
      continue;
    }
    std::size_t j = i;
    for (; j < text.size(); ++j) {
      const auto d = static_cast<unsigned char>(text[j]);
      if (ascii_alnum(d) || d >= 0x80) continue;
      // an apostrophe inside a word ("don't"), not at its end ("the boys' ")
      if (d == '\'' && j + 1 < text.size()) {
        const auto e = static_cast<unsigned char>(text[j + 1]);
        if (ascii_alnum(e) || e >= 0x80) continue;
      }
      break;
    }
    TranscriptWord w{std::string(text.substr(i, j - i)), {}, i};
    for (char ch : w.text) w.key += (ch >= 'A' && ch <= 'Z') ? static_cast<char>(ch - 'A' + 'a') : ch;
    t.words.push_back(std::move(w));
    i = j;
  }
  if (t.words.empty()) throw InputError({source, std::nullopt, std::nullopt}, "transcript-empty", "no word to align");
  return t;
}

}  // namespace fapcast
