#pragma once
// Marker CSV, the plain layout fapcast accepts from tools that export neither C3D nor TRC:
//   # frame_rate_hz=60          (optional lines starting with '#': key=value settings)
//   # units=mm                  (mm, cm, m or in; default mm)
//   frame,time_s,8.1.x,8.1.y,8.1.z,HEAD_L.x,HEAD_L.y,HEAD_L.z
//   1,0,12.5,-3,40.25,,,
// Comma-separated, UTF-8; columns after frame,time_s come in x,y,z triples named LABEL.x LABEL.y
// LABEL.z; all three cells empty = missing sample; frame numbers consecutive. Without a
// frame_rate_hz setting the rate is (frames - 1) / (last time - first time). See spec/corpus.md.
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/marker_frames.hpp"

#include <string>
#include <string_view>

namespace fapcast {

// Parses a marker CSV. Throws InputError ("name:line: csv-...: detail").
MarkerFrames<Millimetres> read_marker_csv(std::string_view bytes, const std::string& source);

// The marker CSV of `markers` (frame_rate_hz and units=mm settings, shortest exact decimals).
// Throws std::invalid_argument if a label is empty or holds a comma, quote or line break.
std::string write_marker_csv(const MarkerFrames<Millimetres>& markers);

}  // namespace fapcast
