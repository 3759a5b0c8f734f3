// `fapcast corpus script`: the recording script of a visual-speech corpus (paper section 3.2).
#include <iostream>

#include "command.hpp"
#include "fapcast/synth/data_dir.hpp"
#include "fapcast/synth/recording_script.hpp"
#include "fapcast/transport/file_io.hpp"

namespace {

// The shared `corpus` command group: whichever command file registers first creates it.
CLI::App* corpus_group(CLI::App& app) {
  try {
    return app.get_subcommand("corpus");
  } catch (const CLI::OptionNotFound&) {
    auto* corpus = app.add_subcommand("corpus", "Build and record a motion-capture corpus");
    corpus->require_subcommand(1);
    return corpus;
  }
}

const fapcast::tools::Registration reg{"50-corpus-script", [](CLI::App& app) {
  struct Args {
    std::string output;
    std::string cmudict = fapcast::synth::default_cmudict_path().string();
    std::string word_counts = fapcast::synth::default_word_counts_path().string();
    fapcast::synth::ScriptOptions options;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = corpus_group(app)->add_subcommand(
      "script", "Write the recording script: common words, syllable-covering words, and "
                "nonsense syllables for every diviseme (greedy coverage); print its coverage");
  cmd->add_option("-o,--output", args->output, "Write the script to FILE (default: standard output)");
  cmd->add_option("--cmudict", args->cmudict, "Syllabified lexicon in Festival format (festlex-cmu)")
      ->capture_default_str();
  cmd->add_option("--word-counts", args->word_counts, "Word counts, word<TAB>count, most frequent first")
      ->capture_default_str();
  cmd->add_option("--common", args->options.common_words, "Number of most common words")->capture_default_str();
  cmd->add_option("--syllable-words", args->options.syllable_words, "Number of syllable-covering words")
      ->capture_default_str();
  cmd->add_option("--candidates", args->options.candidate_words, "Most frequent words considered")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->callback([args] {
    namespace synth = fapcast::synth;
    const auto lexicon = synth::parse_festival_lexicon(fapcast::transport::read_file(args->cmudict), args->cmudict);
    const auto counts = synth::parse_word_counts(fapcast::transport::read_file(args->word_counts), args->word_counts);
    const synth::RecordingScript script = synth::build_recording_script(counts, lexicon, args->options);
    const std::string text = synth::format_recording_script(script);
    if (args->output.empty()) {
      std::cout << text;
      return;
    }
    fapcast::transport::write_file_atomically(args->output, text);
    std::cout << synth::format_coverage(script.coverage) << "# wrote " << script.items.size()
              << " items to " << args->output << "\n";
  });
}};

}  // namespace
