#pragma once
// Gentle's forced-alignment JSON (spec/corpus.md "Gentle JSON").
#include "fapcast/corpus/alignment.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace fapcast {

// Gentle (lowerquality/gentle) JSON: "words" with case "success" carry start, end and phones
// (consecutive from the word's start by their durations); other cases have no timing and are
// counted in `untimed_words`. Tiers "words" and "phones".
struct GentleRead {
  Alignment alignment;
  std::size_t untimed_words = 0;
};
GentleRead read_gentle(std::string_view bytes, const std::string& source);

}  // namespace fapcast
