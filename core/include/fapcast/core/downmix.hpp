#pragma once
// Many channels to one: speech recorded in stereo (or more) animated as the mean of its channels.
#include "fapcast/core/audio.hpp"

namespace fapcast {

// The mean of every channel at each sampling instant, rounded to the nearest integer (halves away
// from zero): mono audio at the same rate with audio.instants() samples. Mono audio is returned
// as it is. Throws std::invalid_argument for a channel count below 1.
Audio downmix_to_mono(const Audio& audio);

}  // namespace fapcast
