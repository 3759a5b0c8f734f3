#pragma once
// Weak forms of English function words (the unstressed readings: "for" as f@, "were" as w@),
// as pronunciation variants for the aligner. spec/recognise.md, "Weak forms", names the source.
#include <string_view>
#include <vector>

namespace fapcast {

// The weak forms of the function word `key` (lower-case), in ARPAbet ("F AH R"; schwa as AH, the
// syllabic consonant of "and" or "can" as the bare consonant). `before_vowel`: the next word starts with a
// vowel, so a word ending in a non-rhotic schwa also gets its linking-r form ("for us": F AH R).
// Empty for a word that is not in the list.
std::vector<std::string_view> weak_forms(std::string_view key, bool before_vowel);

}  // namespace fapcast
