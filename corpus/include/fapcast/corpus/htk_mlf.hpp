#pragma once
// HTK master label files (.mlf): many utterances' label files in one (spec/corpus.md "HTK
// master label files").
#include "fapcast/corpus/label_tier.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

// One utterance of an HTK master label file.
struct MlfEntry {
  std::string pattern;    // as written between the quotes ("*/sa1.lab")
  std::uint64_t line = 0;  // where the pattern is
  LabelTier tier;         // the segments (level 1 labels), seconds, named after the pattern
};
// HTK MLF: "#!MLF!#", then per entry a quoted pattern line, label lines
// "[START [END]] NAME [SCORE] {AUXNAME [AUXSCORE]}" (100 ns units) and a line ".". Entries that
// redirect to a directory ("-> dir", "=> dir") and untimed labels are refused: fapcast reads the
// alignments an MLF holds.
std::vector<MlfEntry> read_mlf(std::string_view bytes, const std::string& source);
// Whether `pattern` (HTK's * and ? allowed) names the utterance `stem` (file name without
// directory and extension): "*/sa1.lab" names "sa1".
bool mlf_pattern_matches(std::string_view pattern, std::string_view stem);

}  // namespace fapcast
