#pragma once
// Electromagnetic articulography (EMA) as MOCHA-TIMIT distributes it: midsagittal coil tracks
// (x, y per coil) in 1/100 mm at 500 Hz, in the Edinburgh Speech Tools Track format, ASCII or
// binary, or as the bare ASCII rows (time, flag, values) of the MOCHAtools conversion. Coils are
// named as MOCHA names them (spec/articulography.md): ui upper incisor, li lower incisor, ul upper
// lip, ll lower lip, tt tongue tip, tb tongue body, td tongue dorsum, v velum, bn nose bridge.
#include "fapcast/corpus/marker_frames.hpp"

#include <string>
#include <string_view>

namespace fapcast {

// Parses an EMA file: one marker per coil, labelled with MOCHA's coil name, positions in mm in the
// file's own frame (x along the talker's front-back axis as recorded, y up, z = 0: the midsagittal
// plane), frame k at first_frame / frame_rate_hz + k / frame_rate_hz seconds; a sample whose frame
// is flagged as a break (no valid data) is missing (NaN). Throws InputError naming the file and the
// line (ASCII) or byte offset (binary) and the rule ("ema-...").
MarkerFrames<Millimetres> read_ema(std::string_view bytes, const std::string& source);

}  // namespace fapcast
