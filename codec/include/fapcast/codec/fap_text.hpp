#pragma once
// Reading and writing `.fap` text files in every dialect real players write (spec/fap-text.md).
#include "fapcast/codec/fap_frame.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace fapcast::codec {

// How the mask lines are laid out.
enum class FapTextDialect {
  kStrict,  // 68 mask tokens; FAP 1 with 4 integers and FAP 2 with 6 (the standard's layout)
  kMask69,  // 69 mask tokens (a leading unused slot); one integer each for FAP 1 and FAP 2
};

// What the reader saw, besides the frames: the dialect and every tolerated irregularity.
struct FapTextInfo {
  std::string version;  // "2.1", "2.0" ...
  FapTextDialect dialect = FapTextDialect::kStrict;
  std::uint64_t header_frame_count = 0;  // what the header claimed
  bool crlf = false;
  bool tabs = false;
  bool comments = false;
  bool name_has_spaces = false;
  bool skipped_frames = false;    // frame numbers skipped; the previous frame was held
  bool real_valued_tokens = false;
  std::vector<std::string> warnings;  // "joy.fap:14: real-value: 3.6 rounded to 4", ...

  // One line naming the dialect and the irregularities, e.g. "68-token masks, CRLF, comments".
  std::string describe() const;
};

struct FapTextRead {
  FapSequence sequence;
  FapTextInfo info;
};

// Parses a whole `.fap` file. `source` names it in messages. Throws InputError (with the line
// and the rule broken) for anything it cannot accept; never allocates from an untrusted count.
FapTextRead read_fap_text(std::string_view bytes, std::string_view source);

// Writes the strict profile by default: "2.1 NAME FPS N", 68-token masks, frames 0..N-1,
// integers, single spaces, LF. kMask69 writes the 69-token dialect (FAP 1 and 2: select1 only).
std::string write_fap_text(const FapSequence& seq, FapTextDialect dialect = FapTextDialect::kStrict);

}  // namespace fapcast::codec
