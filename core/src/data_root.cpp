#include "fapcast/core/data_root.hpp"

#include <cstdlib>

namespace fapcast {

std::filesystem::path data_root() {
  if (const char* env = std::getenv("FAPCAST_DATA"); env != nullptr && *env != '\0') return env;
  return FAPCAST_DATA_DIR;
}

std::filesystem::path default_word_counts_path() {
  return data_root() / "lexicon" / "subtlex-us-top20000.tsv";
}

std::filesystem::path default_cmudict_path() {
  if (const char* env = std::getenv("FAPCAST_CMUDICT"); env != nullptr && *env != '\0') return env;
  return "/usr/share/festival/dicts/cmu/cmudict-0.4.out";
}

}  // namespace fapcast
