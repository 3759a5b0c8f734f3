#pragma once
// Mouth cues in the three result formats of Rhubarb Lip Sync (its README, "Output formats";
// spec/mouth-cues.md, "The files"), so that the integrations written for Rhubarb (Blender, Spine,
// After Effects, game engines) read fapcast's cues: TSV (a "seconds<TAB>shape" line per cue, then
// the recording's end with a closed mouth), XML (<rhubarbResult>: metadata, then <mouthCue start
// end>) and JSON (metadata, mouthCues[]). Times are seconds with two decimals.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/cues/mouth_cues.hpp"

namespace fapcast {

enum class RhubarbFormat : std::uint8_t { kTsv, kXml, kJson };

// "tsv", "xml", "json" (Rhubarb's --exportFormat names), or nullopt.
std::optional<RhubarbFormat> rhubarb_format_from_name(std::string_view name);
// The format of a path's extension (.tsv, .xml, .json, any case), or nullopt.
std::optional<RhubarbFormat> rhubarb_format_from_path(const std::filesystem::path& path);

struct RhubarbResult {
  std::vector<MouthCue> cues;  // mouth_cues(): contiguous from 0 to `duration`
  Centiseconds duration{0};    // the recording's length, truncated to centiseconds
  std::string sound_file;      // the recording's path (metadata of XML and JSON)
  MouthShapeSet drawn = MouthShapeSet::all();  // TSV's closing line: X if drawn, else A
};

// The result as a file of `format` (UTF-8 text, LF line ends).
std::string write_rhubarb(const RhubarbResult& result, RhubarbFormat format);

}  // namespace fapcast
