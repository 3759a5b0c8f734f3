#pragma once
// Where fapcast's runtime data lives (data/ict-facekit, data/lexicon ...).
#include <filesystem>

namespace fapcast::synth {

// The data directory: $FAPCAST_DATA when set and non-empty, else <source tree>/data.
std::filesystem::path data_root();

}  // namespace fapcast::synth
