// `fapcast eval retarget`: retargeting fidelity by the paper's lip measures (section 4.1).
#include "command.hpp"

#include "fapcast/eval/retarget_evaluation.hpp"
#include "fapcast/core/synthetic_label.hpp"
#include "fapcast/voice/voice.hpp"

#include <cstdio>
#include <stdexcept>
#include <filesystem>
#include <iostream>
#include <memory>

namespace {

const fapcast::cli::Registration eval_retarget_command{"eval retarget", [](CLI::App& app) {
  struct Args {
    std::string voice;
    std::string corpus;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = fapcast::cli::command_group(app, "eval", fapcast::cli::kEvalGroupHelp)
                  ->add_subcommand("retarget",
                                   "Lip height, width and protrusion of the source markers against the voice's "
                                   "retargeted target face over a corpus: mean normalised error and correlation");
  cmd->add_option("VOICE", args->voice, "Voice file (.fapv)")->required();
  cmd->add_option("--corpus", args->corpus, "Corpus directory (default: the one the voice was built from)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress on standard error");
  cmd->callback([args] {
    const auto voice = fapcast::Voice::open(args->voice);
    std::string corpus = args->corpus;
    if (corpus.empty()) {
      corpus = voice.provenance().corpus;
      if (!std::filesystem::is_directory(corpus))
        throw std::runtime_error("the voice's corpus \"" + corpus + "\" is not a directory here: pass --corpus DIR");
    }
    const auto e = fapcast::evaluate_retargeting(voice, corpus, [&](std::size_t done, std::size_t total) {
      if (!args->quiet && (done % 50 == 0 || done == total)) std::cerr << "\revaluated " << done << " / " << total << std::flush;
    });
    if (!args->quiet) std::cerr << "\n";
    if (voice.provenance().synthetic) std::cout << fapcast::kSyntheticLabel << "\n";
    std::cout << "retargeting " << corpus << " with " << args->voice << ": " << e.utterances << " utterances, " << e.frames
              << " frames (paper section 4.1; each curve normalised by its maximum)\n";
    std::printf("%-16s %14s %12s %16s %12s %10s\n", "measure", "RBF error %", "RBF corr", "RBF+PCA error %",
                "RBF+PCA corr", "paper %");
    const auto row = [](const char* name, const fapcast::CurveAgreement& a,
                        const fapcast::CurveAgreement& b, const char* paper) {
      std::printf("%-16s %14.3f %12.4f %16.3f %12.4f %10s\n", name, a.mean_error_percent, a.correlation,
                  b.mean_error_percent, b.correlation, paper);
    };
    row("lip height", e.retargeted.height, e.compressed.height, "5.207");
    row("lip width", e.retargeted.width, e.compressed.width, "4.778");
    row("lip protrusion", e.retargeted.protrusion, e.compressed.protrusion, "2.21");
  });
}};

}  // namespace
