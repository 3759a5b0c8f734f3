#pragma once
// Reading and writing `.fap` text files in every dialect real players write (spec/fap-text.md).
#include "fapcast/core/input_error.hpp"
#include "fapcast/codec/fap_frame.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

// How the mask lines are laid out.
enum class FapTextDialect {
  kStrict,  // 68 mask tokens; FAP 1 with 4 integers and FAP 2 with 6 (the standard's layout)
  kMask69,  // 69 mask tokens (a leading unused slot); one integer each for FAP 1 and FAP 2
};

// Limits that keep a hostile file from making the reader allocate without bound
// (spec/fap-text.md, "Limits"). Memory is bounded by what the file actually holds, never by
// the header's claim.
inline constexpr std::uint64_t kFapTextMaxFrames = 1'000'000;  // 11 h at 25 fps
inline constexpr std::uint64_t kFapTextMaxHeldFrames = 1'000;  // one skip holds <= 40 s at 25 fps
inline constexpr std::size_t kFapTextMaxWarnings = 32;         // further ones are only counted

// What the reader saw, besides the frames: the dialect and every tolerated irregularity.
struct FapTextInfo {
  std::string version;  // "2.1", "2.0" ...
  FapTextDialect dialect = FapTextDialect::kStrict;
  std::uint64_t header_frame_count = 0;  // what the header claimed
  std::uint64_t frame_records = 0;       // mask+value pairs in the file (held frames excluded)
  bool utf8_bom = false;  // the file starts with a UTF-8 byte-order mark (skipped)
  bool crlf = false;
  bool tabs = false;
  bool comments = false;
  bool name_has_spaces = false;
  bool skipped_frames = false;    // frame numbers skipped; the previous frame was held
  bool real_valued_tokens = false;
  bool header_count_short = false;  // the file holds slightly fewer frames than the header says
  bool single_fap12 = false;  // 68-token masks with FAP 1 and FAP 2 as one integer each (Greta, VREng)
  bool one_based = false;     // frames numbered 1..N under a count of N, read as 0..N-1
  std::vector<std::string> warnings;  // "joy.fap:14: real-value: 3.6 rounded to 4", ...
  std::uint64_t warning_count = 0;    // all warnings, including those beyond kFapTextMaxWarnings

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
// The name is written as fap_text_name(seq.name). Throws std::invalid_argument when the rate
// has no exact decimal form the reader maps back to it (fap_text_fps), or for more than
// kFapTextMaxFrames frames: the writer writes only what the reader reads back.
std::string write_fap_text(const FapSequence& seq, FapTextDialect dialect = FapTextDialect::kStrict);

// The players whose own parsers fapcast writes for (spec/fap-text.md, "Players").
enum class FapPlayer { kXface, kGreta, kVreng };
// "xface", "greta", "vreng" (nullopt for any other name), and back.
std::optional<FapPlayer> fap_player_from_name(std::string_view name);
const char* fap_player_name(FapPlayer player);
struct FapTextWriteOptions {
  FapTextDialect dialect = FapTextDialect::kStrict;
  // nullopt: the strict standard layout. A player: exactly what that player parses as intended
  // (Xface: the strict layout, an integer fps; Greta and VREng: FAP 1 and FAP 2 one integer each).
  std::optional<FapPlayer> player;
};
// As write_fap_text(seq, dialect), for a player. Throws std::invalid_argument where the player
// cannot read `seq` as intended (Xface and a rate that is not a whole number of frames a second).
std::string write_fap_text(const FapSequence& seq, const FapTextWriteOptions& options);
// How the three players would read `seq` written with `options` otherwise than intended, one
// note each; empty when Xface, Greta and VREng all read it as written.
std::vector<std::string> fap_text_player_notes(const FapSequence& seq, const FapTextWriteOptions& options);

// What the players' notes depend on: the rate, whether any frame masks FAP 1 or 2, and how
// many frames the one-field layout cannot carry (mask69_lossy_frames).
struct FapTextStats {
  FrameRate rate;
  bool fap12 = false;
  std::size_t mask69_lossy = 0;
};
std::vector<std::string> fap_text_player_notes(const FapTextStats& stats, const FapTextWriteOptions& options);

// write_fap_text(seq, options) a frame at a time, for a track too long to hold whole: append()
// adds each frame's lines (numbered in order), header() is then the first line for the frames
// appended. Header then frames are the bytes write_fap_text gives for the same frames. Throws
// std::invalid_argument as write_fap_text does (the rate, on construction; the frame count).
class FapTextFrameWriter {
 public:
  FapTextFrameWriter(FrameRate rate, const FapTextWriteOptions& options);
  void append(std::string& out, const FapFrame& frame);
  std::string header(std::string_view name) const;
  std::uint64_t frames() const { return frames_; }
  const FapTextStats& stats() const { return stats_; }

 private:
  bool mask69_ = false;
  bool single_ = false;
  std::uint64_t frames_ = 0;
  FapTextStats stats_;
};

// The header's name token for `name`: invalid UTF-8 becomes U+FFFD, every space, tab or
// control character becomes '_', and an empty name becomes "unnamed" — so that readers that
// take the name as one token stay in step.
std::string fap_text_name(std::string_view name);

// The header's fps token for `rate`: "25", "12.5", and "29.97" for 30000/1001 (the reader maps
// 29.97 back to 30000/1001). Throws std::invalid_argument for a rate with no such form (10/3).
std::string fap_text_fps(FrameRate rate);

// The frame as the 69-token dialect carries it: FAP 1 keeps viseme_select1 at full weight
// (blend 63), FAP 2 keeps expression_select1 at full intensity (63); everything else is as is.
FapFrame as_mask69(const FapFrame& frame);

// How many frames the 69-token dialect cannot carry exactly (as_mask69(f) != f).
std::size_t mask69_lossy_frames(const FapSequence& seq);

}  // namespace fapcast
