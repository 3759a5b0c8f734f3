#pragma once
// Electromagnetic articulography (EMA) as MOCHA-TIMIT distributes it: midsagittal coil tracks
// (x, y per coil) in 1/100 mm at 500 Hz, in the Edinburgh Speech Tools Track format, ASCII or
// binary, or as the bare ASCII rows (time, flag, values) of the MOCHAtools conversion. Coils are
// named as MOCHA names them (spec/articulography.md "EMA files"): li lower incisor, ul upper lip,
// ll lower lip, tt tongue tip, tb tongue body, td tongue dorsum, v velum, ui upper incisor, bn
// bridge of the nose.
#include "fapcast/corpus/marker_frames.hpp"

#include <array>
#include <string>
#include <string_view>

namespace fapcast {

// MOCHA's coil names in MOCHA's documented order (lower incisor, upper lip, lower lip, tongue
// tip, body, dorsum, velum, upper incisor, nose bridge): the order read_ema returns them in.
inline constexpr std::array<std::string_view, 9> kMochaCoils = {"li", "ul", "ll", "tt", "tb",
                                                                 "td", "v",  "ui", "bn"};

// Parses an EMA file: one marker per coil the file has (an x and a y channel named <coil>_x,
// <coil>_y; the headerless form has all nine), in kMochaCoils order, labelled with MOCHA's coil
// name, positions in mm in the file's own frame (x along the talker's front-back axis as
// recorded, y up, z = 0: the midsagittal plane), frame k at first_frame / frame_rate_hz +
// k / frame_rate_hz seconds; a frame flagged as a break (no valid data) is missing (NaN).
// Throws InputError naming the file and the line (text) or byte offset (binary data) and the
// rule ("ema-...").
MarkerFrames<Millimetres> read_ema(std::string_view bytes, const std::string& source);

// The EST Track encodings write_ema_est can produce.
enum class EstEncoding {
  ascii,                 // DataType ascii
  binary_little_endian,  // DataType binary, ByteOrder 01, float32
  binary_big_endian,     // DataType binary, ByteOrder 10, float32 (as Sun machines wrote it)
};

// The EST Track file of `markers` (FrameShift 1 / rate; channels <coil>_x, <coil>_y per marker, 1/100 mm, a time
// and a break column; a frame with every coil missing is a break), which read_ema reads back
// (binary: to float32 precision). Throws std::invalid_argument for labels that are not MOCHA
// coil names or repeat, a non-zero z, a frame with some coils missing and some not, a rate
// that is not positive, or (binary) a value that does not fit a float.
std::string write_ema_est(const MarkerFrames<Millimetres>& markers, EstEncoding encoding);

}  // namespace fapcast
