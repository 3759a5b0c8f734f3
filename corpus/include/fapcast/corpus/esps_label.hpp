#pragma once
// ESPS/xlabel label files (Entropic; Festival, EMU and Edinburgh Speech Tools write them):
// segment end times in seconds (spec/corpus.md "ESPS / xlabel / Festival").
#include "fapcast/corpus/label_tier.hpp"

#include <string>
#include <string_view>

namespace fapcast {

// ESPS xlabel (Entropic), as Festival, EMU and Edinburgh Speech Tools write it: header lines
// ("signal x", "nfields 1", "separator ;", ...) up to a line "#", then one row per segment
// "END_TIME COLOUR LABEL": times are segment ends in seconds, the first segment starts at 0.
// With "separator C" the label is the text before the first C; otherwise the rest of the row.
LabelTier read_esps_label(std::string_view bytes, const std::string& source, std::string tier_name);

}  // namespace fapcast
