#pragma once
// FAP tracks in files, chosen by extension: .fap (text, spec/fap-text.md), .fba (bitstream,
// spec/fba.md) and .json (spec/json.md). Reads are size-limited, writes atomic.
#include "fapcast/core/input_error.hpp"
#include "fapcast/codec/fap_frame.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace fapcast {

enum class TrackFormat { kFapText, kFba, kJson };

// The format named by the file's extension (case-insensitive); nullopt for any other.
std::optional<TrackFormat> track_format_of(const std::filesystem::path& path);

// Reads a whole track. Throws (std::runtime_error, InputError) naming the file and the
// rule broken; an .fba with any corrupt plane is refused with its first error.
FapSequence read_track_file(const std::filesystem::path& path);

// Writes `seq` atomically in the format of the extension. `sample_rate` adds each frame's WAV
// sample to JSON output. Throws std::runtime_error naming the file on failure.
void write_track_file(const std::filesystem::path& path, const FapSequence& seq,
                      std::optional<std::int64_t> sample_rate = std::nullopt);

}  // namespace fapcast
