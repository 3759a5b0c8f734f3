#include "recording_script_options.hpp"

#include "fapcast/core/data_root.hpp"
#include "fapcast/corpus/syllabified_lexicon.hpp"
#include "fapcast/core/file_io.hpp"

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
  const auto counts = parse_word_counts(read_file(in.word_counts), in.word_counts);
  return build_recording_script(counts, lexicon, in.options);
}

}  // namespace fapcast::cli
