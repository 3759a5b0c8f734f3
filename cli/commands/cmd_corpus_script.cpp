// `fapcast corpus script`: the recording script of a visual-speech corpus (paper section 3.2).
#include <iostream>

#include "command.hpp"
#include "output_check.hpp"
#include "recording_script_options.hpp"
#include "fapcast/corpus/recording_script.hpp"
#include "fapcast/core/file_io.hpp"

namespace {

const fapcast::cli::Registration corpus_script_command{"corpus script", [](CLI::App& app) {
  struct Args {
    std::string output;
    fapcast::cli::RecordingScriptInputs inputs;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = fapcast::cli::command_group(app, "corpus", fapcast::cli::kCorpusGroupHelp)->add_subcommand(
      "script", "Write the recording script: common words, syllable-covering words, and "
                "nonsense syllables for every diviseme (greedy coverage); print its coverage");
  cmd->add_option("-o,--output", args->output, "Write the script to FILE (default: standard output)");
  fapcast::cli::add_recording_script_options(cmd, args->inputs);
  cmd->callback([args] {
    fapcast::cli::check_output_writable(args->output);
    const fapcast::RecordingScript script = fapcast::cli::load_recording_script(args->inputs);
    const std::string text = fapcast::format_recording_script(script);
    if (args->output.empty()) {
      std::cout << text;
      return;
    }
    fapcast::write_file_atomically(args->output, text);
    std::cout << fapcast::format_coverage(script.coverage) << "# wrote " << script.items.size()
              << " items to " << args->output << "\n";
  });
}};

}  // namespace
