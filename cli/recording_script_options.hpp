#pragma once
// The options that say where a recording script comes from, shared by `corpus script` and
// `corpus record-reference`.
#include "fapcast/corpus/recording_script.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace fapcast::cli {

// Help text of the `corpus` command group.
inline constexpr const char* kCorpusGroupHelp =
    "Write a recording script; record the (SYNTHETIC) reference corpus";

struct RecordingScriptInputs {
  std::string cmudict;      // Festival-format syllabified lexicon
  std::string word_counts;  // word<TAB>count, most frequent first
  ScriptOptions options;
};

// Adds --cmudict, --word-counts, --common, --syllable-words, --candidates to `cmd`.
void add_recording_script_options(CLI::App* cmd, RecordingScriptInputs& inputs);

// Reads the lexicon and the word counts and builds the script.
RecordingScript load_recording_script(const RecordingScriptInputs& inputs);

}  // namespace fapcast::cli
