// `fapcast eval align DATA [--recording NAME]... [--lang L] [--json-out FILE] [-q]`: the forced aligner with
// the transcript and the recogniser without it, scored against the reference labels vendored
// under DATA (the repository's tests/data), per data set (spec/recognise.md, "Accuracy").
// Argument parsing only.
#include "command.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/eval/alignment_evaluation.hpp"
#include "fapcast/frontend/espeak_language.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {
using namespace fapcast;

const cli::Registration eval_align_command{"eval align", [](CLI::App& app) {
  struct Args {
    std::string data;                     // DATA
    std::vector<std::string> recordings;  // --recording, repeatable
    std::string lang;                     // --lang: AlignerSettings::language
    std::string json;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = cli::command_group(app, "eval", cli::kEvalGroupHelp)->add_subcommand("align",
      "Score forced alignment (with the transcript: boundaries within 10/20/25/50 ms) and recognition (without: "
      "frames in the right viseme class) against reference labels of real recordings");
  cmd->add_option("DATA", args->data, "The folder of the vendored references: the repository's tests/data")->required();
  cmd->add_option("--recording", args->recordings,
                  "Score only this recording (msajc003 ... msajc057, fsew0_001, a0009); repeatable");
  cmd->add_option("--lang", args->lang,
                  "Align every recording as read in this accent, an espeak-ng language (`espeak-ng --voices`: en-gb, "
                  "...): espeak-ng's reading of each word is one more pronunciation (spec/recognise.md, \"Accents\"); "
                  "default: the US dictionary's only");
  cmd->add_option("--json-out", args->json, "Write the results as JSON to this file (atomically)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress on standard error");
  cmd->callback([args] {
    if (!args->lang.empty() && !espeak_language_installed(args->lang))
      throw cli::UsageError("eval align: --lang '" + args->lang +
                            "': not an installed espeak-ng language (espeak-ng --voices lists them)");
    std::vector<ReferenceRecording> chosen;
    for (const ReferenceRecording& r : reference_recordings(args->data))
      if (args->recordings.empty() ||
          std::find(args->recordings.begin(), args->recordings.end(), r.name) != args->recordings.end())
        chosen.push_back(r);
    for (const std::string& name : args->recordings)
      if (std::none_of(chosen.begin(), chosen.end(), [&](const ReferenceRecording& r) { return r.name == name; }))
        throw cli::UsageError("eval align: no reference recording '" + name + "'");
    if (!args->quiet) std::cerr << "aligning and recognising " << chosen.size() << " recordings\n";
    std::string command = "fapcast eval align " + args->data;
    for (const std::string& name : args->recordings) command += " --recording " + name;
    if (!args->lang.empty()) command += " --lang " + args->lang;
    const std::vector<AlignmentScore> scores = evaluate_alignment(chosen, args->lang);
    std::cout << format_alignment_table(scores, command);
    if (!args->json.empty()) write_file_atomically(args->json, alignment_json(scores, command).dump(2) + "\n");
  });
}};

}  // namespace
