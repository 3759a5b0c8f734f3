#pragma once
// A phone and its span on the WAV timeline: what the text front-end, an alignment (TextGrid,
// .lab), the reference talker and synthesis pass between them. Times are samples of the
// utterance's audio; what only the front-end knows of a phone stays in its Speech.
#include <cstdint>

#include "fapcast/phonetics/phone.hpp"

namespace fapcast {

struct TimedPhone {
  Phone phone;
  std::int64_t start_sample;  // first sample of the phone's segment (for has_closure(): the closure)
  std::int64_t end_sample;    // one past its last: the next phone's start_sample, or the audio's length
  friend bool operator==(const TimedPhone&, const TimedPhone&) = default;
};

}  // namespace fapcast
