#pragma once
// A capture take starts and ends with the talker at rest: the face is recorded for a while before
// the first word and after the last (MOCHA-TIMIT's fsew0_001: 0.35 s before, 0.53 s after). The
// voice's silence class and the return to rest after speech are learnt from these stretches;
// espeak-ng's own edge pauses are a few milliseconds long (spec/talker.md, "Rest before and after").
#include "fapcast/frontend/text_frontend.hpp"

namespace fapcast {

// How long the reference talker rests before and after each take.
struct RestPadding {
  double before_s = 0.25;
  double after_s = 0.35;
};

// `speech` with silent audio added before and after it and every sample position shifted: the
// first and last phones become silences reaching the new edges (a silence phone is extended, else
// one is added from the edge to the nearest phone, with its event, word kNoWord). Throws std::invalid_argument for a negative padding.
Speech with_rest(Speech speech, const RestPadding& padding);

}  // namespace fapcast
