#pragma once
// C3D motion-capture files (c3d.org): 512-byte header block, parameter section (groups and
// parameters), then per frame the 3-D points (X Y Z and a residual word; a negative residual
// marks a missing sample) followed by analog samples, which the reader skips. Integer storage
// (POINT:SCALE > 0) and float storage (POINT:SCALE < 0) are read; only Intel byte order
// (processor type 84) is supported, DEC (85) and MIPS (86) files are refused by name. Every
// offset and count is checked against the file size before use. Rules in spec/corpus.md.
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/marker_frames.hpp"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

struct C3dFile {
  MarkerFrames<Millimetres> markers;  // converted to mm from POINT:UNITS; unlabelled markers are named "*N"
  // Every character parameter as "GROUP:NAME" -> text (names upper-cased; a 2-D array's rows are
  // trimmed of trailing spaces and joined with '\n'), e.g. "FAPCAST:SYNTHETIC".
  std::map<std::string, std::string> text_parameters;
  bool float_storage = true;  // POINT:SCALE < 0
  double point_scale = -1;    // POINT:SCALE as stored
  std::string units = "mm";   // POINT:UNITS as stored (positions are converted to mm)
};

// A free-form character parameter to write, e.g. {"FAPCAST", "SYNTHETIC", kSyntheticLabel}.
// Group and name: 1 to 32 of A-Z 0-9 _; value at most 255 bytes.
struct C3dTextParameter {
  std::string group;
  std::string name;
  std::string value;
  std::string description;  // at most 255 bytes
};

// Parses a C3D file's bytes. Throws InputError ("name: byte 512: c3d-...: detail").
C3dFile read_c3d(std::string_view bytes, const std::string& source);

// An Intel float C3D (POINT:SCALE -1, units mm, first frame 1) of `markers`, with POINT:LABELS
// (and LABELS2 ... when needed), POINT:RATE, POINT:UNITS "mm", ANALOG:USED 0 and the `extra`
// parameters. Missing samples are written as 0 0 0 with residual -1. Reading it back gives the
// same markers exactly when the positions are floats. Throws std::invalid_argument if the set does
// not fit C3D (more than 65535 frames or markers, inconsistent shapes, bad labels or names).
std::string write_c3d(const MarkerFrames<Millimetres>& markers, const std::vector<C3dTextParameter>& extra = {});

// The parameter that marks a file as written by the reference talker (FAPCAST:SYNTHETIC).
C3dTextParameter c3d_synthetic_parameter();

}  // namespace fapcast
