#pragma once
// TIMIT .phn/.wrd label files: segments in samples of the recording (spec/corpus.md "TIMIT").
#include "fapcast/corpus/label_tier.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace fapcast {

// TIMIT .phn / .wrd: "BEGIN END LABEL" in samples of the recording (16 kHz in TIMIT itself).
LabelTier read_timit_label(std::string_view bytes, const std::string& source, SampleRate sample_rate,
                           std::string tier_name);

}  // namespace fapcast
