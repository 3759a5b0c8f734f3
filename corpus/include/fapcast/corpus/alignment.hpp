#pragma once
// A time alignment of one utterance: named tiers over one time span (what a TextGrid holds),
// typically "phones" and "words" interval tiers.
#include "fapcast/corpus/label_tier.hpp"

#include <string_view>
#include <vector>

namespace fapcast {

struct Alignment {
  double start_s = 0;  // the span every tier lies in, seconds
  double end_s = 0;
  std::vector<LabelTier> tiers;  // in file order; names need not be unique (Praat allows it)

  // The first tier called `name`, or nullptr.
  const LabelTier* find(std::string_view name) const;
  bool operator==(const Alignment&) const = default;
};

std::ostream& operator<<(std::ostream& out, const Alignment& alignment);

// Appends a TextTier "provenance" with one point at start_s marked kSyntheticLabel: how a
// TextGrid from the reference talker says it is synthetic (Praat shows it, tools ignore it).
void mark_synthetic(Alignment& alignment);

// Whether `alignment` carries the mark that mark_synthetic adds.
bool is_synthetic(const Alignment& alignment);

}  // namespace fapcast
