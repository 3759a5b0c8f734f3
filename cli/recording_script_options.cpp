#include "recording_script_options.hpp"

#include "fapcast/core/data_root.hpp"
#include "fapcast/corpus/syllabified_lexicon.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/core/input_error.hpp"

namespace fapcast::cli {

void add_recording_script_options(CLI::App* cmd, RecordingScriptInputs& in) {
  in.cmudict = default_cmudict_path().string();
  in.word_counts = default_word_counts_path().string();
  cmd->add_option("--cmudict", in.cmudict, "Syllabified lexicon in Festival format (festlex-cmu)")
      ->capture_default_str();
  cmd->add_option("--word-counts", in.word_counts, "Word counts, word<TAB>count, most frequent first")
      ->capture_default_str();
  cmd->add_option("--common", in.options.common_words, "Number of most common words")->capture_default_str();
  cmd->add_option("--syllable-words", in.options.syllable_words, "Number of syllable-covering words")
      ->capture_default_str();
  cmd->add_option("--candidates", in.options.candidate_words, "Most frequent words considered")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
}

RecordingScript load_recording_script(const RecordingScriptInputs& in) {
  const auto lexicon = parse_festival_lexicon(read_file(in.cmudict), in.cmudict);
  if (lexicon.empty())
    throw InputError::in_file(in.cmudict, 0, "lexicon-empty", "the lexicon has no entries");
  const auto counts = parse_word_counts(read_file(in.word_counts), in.word_counts);
  if (counts.empty())
    throw InputError::in_file(in.word_counts, 0, "word-counts-empty", "the word counts have no words");
  RecordingScript script = build_recording_script(counts, lexicon, in.options);
  // A script of nonsense syllables alone is not what was asked for: the two files do not match.
  if (script.coverage.candidate_words == 0)
    throw InputError::in_file(in.cmudict, 0, "lexicon-no-words",
                              "none of the " + std::to_string(in.options.candidate_words) +
                                  " most frequent words of " + in.word_counts + " is in the lexicon");
  return script;
}

}  // namespace fapcast::cli
