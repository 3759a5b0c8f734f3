#pragma once
// FAP tracks in files, chosen by extension: .fap (text, spec/fap-text.md), .fba (bitstream,
// spec/fba.md) and .json (spec/json.md). Reads are size-limited, writes atomic.
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/codec/fap_text.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fapcast {

enum class TrackFormat { kFapText, kFba, kJson };

// The format named by the file's extension (case-insensitive); nullopt for any other.
std::optional<TrackFormat> track_format_of(const std::filesystem::path& path);

// Reads a whole track. Throws (std::runtime_error, InputError) naming the file and the
// rule broken; an .fba with any corrupt plane is refused with its first error.
FapSequence read_track_file(const std::filesystem::path& path);

struct TrackWriteOptions {
  std::optional<SampleRate> sample_rate;  // .json: each frame's WAV sample
  FapTextWriteOptions fap;                // .fap: dialect and player (spec/fap-text.md)
};

// A track in the format of a file's extension, not yet written: its bytes, and what a user
// should know about the file, one line each (the players' notes of a .fap, the profile of an .fba).
struct TrackFileBytes {
  std::string bytes;
  std::vector<std::string> notes;
};

// The bytes of `seq` in the format of the extension of `path` (which is not written); .fba
// losslessly: the standard syntax at fap_quant 0 where it codes every value, else the fapcast
// profile (spec/fba.md §9). Throws std::runtime_error naming the file when it cannot be coded.
TrackFileBytes track_file_bytes(const std::filesystem::path& path, const FapSequence& seq,
                                const TrackWriteOptions& options = {});

// Writes track_file_bytes(path, seq, options) atomically and returns its notes. Throws
// std::runtime_error naming the file on failure.
std::vector<std::string> write_track_file(const std::filesystem::path& path, const FapSequence& seq,
                                          const TrackWriteOptions& options = {});

}  // namespace fapcast
