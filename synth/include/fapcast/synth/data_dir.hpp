#pragma once
// Where fapcast's runtime data (synth/data, see its README.md) and the system lexicon live.
#include <filesystem>

namespace fapcast::synth {

// $FAPCAST_DATA if set and non-empty, else the synth/data directory of the source tree this
// library was compiled from.
std::filesystem::path data_dir();

// The vendored SUBTLEX-US word counts: data_dir() / "lexicon/subtlex-us-top20000.tsv".
std::filesystem::path default_word_counts_path();

// $FAPCAST_CMUDICT if set, else Debian festlex-cmu's /usr/share/festival/dicts/cmu/cmudict-0.4.out.
std::filesystem::path default_cmudict_path();

}  // namespace fapcast::synth
