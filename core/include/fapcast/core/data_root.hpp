#pragma once
// Where fapcast's runtime data lives (data/README.md: data/ict-facekit, data/lexicon ...).
#include <filesystem>

namespace fapcast {

// The data directory: $FAPCAST_DATA when set and non-empty, else <source tree>/data.
std::filesystem::path data_root();

// The vendored SUBTLEX-US word counts: data_root() / "lexicon/subtlex-us-top20000.tsv".
std::filesystem::path default_word_counts_path();

// $FAPCAST_CMUDICT if set, else Debian festlex-cmu's /usr/share/festival/dicts/cmu/cmudict-0.4.out.
std::filesystem::path default_cmudict_path();

}  // namespace fapcast
