#pragma once
// TRC marker files (Motion Analysis / Vicon export, read by OpenSim): tab-separated, a
// "PathFileType" line, a line of keys (DataRate CameraRate NumFrames NumMarkers Units
// OrigDataRate OrigDataStartFrame OrigNumFrames) and their values, a "Frame# Time name ..." row,
// an "X1 Y1 Z1 ..." row, then one row per frame; empty cells mark a missing sample.
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/marker_frames.hpp"

#include <string>
#include <string_view>

namespace fapcast {

// Parses a TRC file; positions converted to mm from Units. NumFrames and NumMarkers are checked
// against the rows and names actually present. Throws InputError ("name:line: trc-...: detail").
MarkerFrames<Millimetres> read_trc(std::string_view bytes, const std::string& source);

// The TRC text of `markers` (Units mm, shortest exact decimals, empty cells where missing).
// Throws std::invalid_argument if labels are empty or hold tabs or line breaks.
std::string write_trc(const MarkerFrames<Millimetres>& markers, std::string_view file_name = "markers.trc");

}  // namespace fapcast
