#include "fapcast/synth/data_dir.hpp"

#include <cstdlib>

namespace fapcast::synth {

std::filesystem::path data_dir() {
  if (const char* env = std::getenv("FAPCAST_DATA"); env != nullptr && *env != '\0') return env;
  // This file is synth/src/data_dir.cpp; the build passes it by absolute path, so its
  // location names the source tree without a CMake-level definition.
  return std::filesystem::path(__FILE__).parent_path().parent_path() / "data";
}

std::filesystem::path default_word_counts_path() { return data_dir() / "lexicon" / "subtlex-us-top20000.tsv"; }

std::filesystem::path default_cmudict_path() {
  if (const char* env = std::getenv("FAPCAST_CMUDICT"); env != nullptr && *env != '\0') return env;
  return "/usr/share/festival/dicts/cmu/cmudict-0.4.out";
}

}  // namespace fapcast::synth
