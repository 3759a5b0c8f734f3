#pragma once
// A phone and its span on the WAV timeline: what the text front-end, an alignment (TextGrid,
// .lab) and synthesis pass between them. Times are samples of the utterance's audio.
#include <cstdint>
#include <string>

#include "fapcast/phonetics/phone.hpp"

namespace fapcast {

inline constexpr int kNoWord = -1;

struct TimedPhone {
  Phone phone;
  std::int64_t start_sample;    // segment start: the closure for has_closure() phones
  std::int64_t end_sample;      // = next phone's start_sample (or the audio length)
  std::int64_t event_sample;    // where espeak-ng's phoneme event put the phone
  std::int64_t release_sample;  // end of the closure's quiet stretch; = start for other phones
  int word;                     // index into Speech::words, kNoWord for silence
  std::string espeak;           // the espeak-ng mnemonic reported
  friend bool operator==(const TimedPhone&, const TimedPhone&) = default;
};

}  // namespace fapcast
