#pragma once
// The default voice (spec/architecture.md, "The default world"): built from the SYNTHETIC
// reference corpus (seed 1) on first use and cached, so `say` and `animate` work without --voice.
#include "fapcast/voice/voice.hpp"

#include <filesystem>
#include <string>

namespace fapcast::cli {

// $FAPCAST_CACHE_DIR, else $XDG_CACHE_HOME/fapcast, else ~/.cache/fapcast; then
// reference-seed1-KEY.fapv, KEY = default_voice_key(1) (default_voice_key.hpp): a voice cached
// from other talker tables or another build recipe is not used.
std::filesystem::path default_voice_path();

// The default voice's path, building it first when the cache has none: records the reference
// corpus (all script items, seed 1) into a temporary directory in a child process (`fapcast
// corpus record-reference`: espeak-ng starts from its initial state, whatever this process spoke
// before), builds the voice (exact PCA route), writes it atomically and removes the corpus.
// Progress on stderr unless `quiet`. Deterministic: the same bytes every time when
// SOURCE_DATE_EPOCH is set (build time). Only the fapcast executable calls it (/proc/self/exe).
std::filesystem::path ensure_default_voice(bool quiet);

// The provenance build time: SOURCE_DATE_EPOCH (reproducible builds) when set, else now; ISO 8601
// UTC ("2026-11-22T04:00:00Z"). Throws std::runtime_error (bad input) when SOURCE_DATE_EPOCH is not a
// non-negative integer.
std::string voice_build_time_utc();

// Opens `path`, or the default voice (built on first use) when it is empty.
Voice open_voice_or_default(const std::filesystem::path& path, bool quiet);

}  // namespace fapcast::cli
