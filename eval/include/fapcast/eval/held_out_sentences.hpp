#pragma once
// Sentences for held-out evaluation of synthesis (`fapcast eval synth`). Written for this
// project. The reference corpus (recording_script.hpp) records single words and nonsense
// syllables only, so no voice built from it has seen any of these as an utterance: their
// coarticulation across word boundaries and their timing are new to it. Chosen to mix closures
// (p b m, f v), rounding (w, uw, ow), spreading (iy), open vowels and long and short words.
#include <array>
#include <string_view>

namespace fapcast {

inline constexpr std::array<std::string_view, 20> kHeldOutSentences{
    "We moved the blue boat to the far side of the pool.",
    "Maybe the chef will bring fresh plums for lunch.",
    "Show me the way to the old mill by the river.",
    "Five brave foxes jumped over a wide muddy ditch.",
    "Please put the warm soup bowls back on the shelf.",
    "Our new puppy chews every shoe it can find.",
    "The museum opens at nine on most Thursdays.",
    "Bob thought the yellow paint looked too bright.",
    "Victor measured the room with a cheap wooden ruler.",
    "You should wash your hands before you eat.",
    "A few sheep wandered through the open gate.",
    "My brother played the violin while we sang.",
    "The judge asked who owned the broken umbrella.",
    "She bought a pair of purple gloves in the market.",
    "Owls hoot softly when the moon is full.",
    "Keep the map in your pocket until we arrive.",
    "Wendy rarely forgets to feed the goldfish.",
    "The pilot waved from the window of the plane.",
    "Both boys laughed when the balloon popped.",
    "Few people ever visit that quiet beach in June.",
};

}  // namespace fapcast
