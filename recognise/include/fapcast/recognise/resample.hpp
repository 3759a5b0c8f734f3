#pragma once
// Speech at another sampling rate: libsamplerate's medium sinc converter (Debian libsamplerate0;
// 90 % of the band kept: 7.2 kHz at 16 kHz, past the recogniser's 6.8 kHz filter bank), audio
// of two or more channels mixed down to their mean first (downmix_to_mono).
#include "fapcast/core/audio.hpp"
#include "fapcast/core/sample_rate.hpp"

namespace fapcast {

// Lowest and highest rates the recogniser takes, in and out.
inline constexpr SampleRate kMinSpeechRate{8000};
inline constexpr SampleRate kMaxSpeechRate{192000};

// `audio` as mono at `rate` (kMinSpeechRate..kMaxSpeechRate): the same samples when it already
// is mono at that rate. Throws std::invalid_argument for a rate out of that range, either way.
Audio resample_mono(const Audio& audio, SampleRate rate);

}  // namespace fapcast
