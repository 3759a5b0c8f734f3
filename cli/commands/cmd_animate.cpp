// `fapcast animate SPEECH.wav ALIGNMENT -o OUT.fap [--voice V] [--tier T] [--phone-set S] ...`: animates
// recorded speech from its phone alignment (spec/synthesis.md); or, with `--transcript FILE` or
// `--text TEXT` instead of the alignment, from the phones the forced aligner finds in it, or with
// neither, from the phones of the words recognised in it (spec/recognise.md). Argument parsing only.
#include "command.hpp"
#include "file_extension.hpp"
#include "speech_transcript.hpp"
#include "synthesis_cli.hpp"

#include "recorded_speech.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/corpus/textgrid.hpp"
#include "fapcast/recognise/speech_alignment.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace {
using namespace fapcast;

template <typename Args>
void animate_from_transcript(const Args& args) {
  if (!args.alignment_out.empty() && cli::lower_extension(args.alignment_out) != ".textgrid")
    throw cli::UsageError("animate: --alignment-out writes a .TextGrid, not '" + args.alignment_out + "'");
  const SpeechAlignment found = cli::align_recording(args.wav, args.transcript, args.synthesis.quiet);
  if (!args.alignment_out.empty()) write_file_atomically(args.alignment_out, write_textgrid(to_alignment(found)));
  const std::vector<TimedPhone> phones = timed_phones(found);
  cli::synthesize_to_file(args.synthesis, phones, found.sample_rate, found.samples, args.wav, "fapcast animate");
}

const cli::Registration animate_command{"animate", [](CLI::App& app) {
  struct Args {
    std::string wav;
    std::string align;
    cli::AlignmentArgs alignment;
    cli::TranscriptArgs transcript;
    std::string alignment_out;
    cli::SynthesisArgs synthesis;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = cli::add_synthesis_command(
      app, "animate", "Animate recorded speech from its WAV and phone alignment (TextGrid, .lab, .phn, .mlf, .par, Gentle .json)",
      args->synthesis, [args] {
        args->synthesis.cues.sound_file = args->wav;
        const int sources = !args->align.empty() + args->transcript.file_given() + args->transcript.text_given();
        if (sources > 1)
          throw cli::UsageError("animate: give the speech's ALIGNMENT, or its --transcript FILE, or its --text TEXT "
                                "(at most one; with none, what it says is recognised)");
        if (!args->align.empty() && !args->alignment_out.empty())
          throw cli::UsageError("animate: --alignment-out writes the alignment found (from --transcript, --text or "
                                "recognition), not an ALIGNMENT given");
        if (!args->align.empty() && !args->transcript.lang.empty())
          throw cli::UsageError("animate: --lang is the accent of a transcript or recognition, not of an ALIGNMENT given");
        if (args->align.empty()) {
          if (!args->alignment.tier.empty() || !args->alignment.phone_set.empty())
            throw cli::UsageError("animate: --tier and --phone-set read an ALIGNMENT file");
          animate_from_transcript(*args);
          return;
        }
        const cli::RecordedPhones speech =
            cli::phones_from_alignment(args->wav, args->align, args->alignment, "animate", args->synthesis.quiet);
        cli::synthesize_to_file(args->synthesis, speech.phones, speech.sample_rate, speech.samples, args->align,
                                "fapcast animate");
      });
  cmd->add_option("SPEECH", args->wav, "The speech (WAV; two or more channels are downmixed to their mean): the timeline")
      ->required();
  cmd->add_option("ALIGNMENT", args->align,
                  "Its phone alignment: Praat TextGrid (text, binary, chronological), HTK .lab/.mlf, ESPS/Festival .lab, "
                  "TIMIT .phn, BAS .par, Gentle .json (spec/corpus.md); or none: found with --transcript or --text, "
                  "else by recognising what the speech says");
  cli::add_transcript_options(*cmd, args->transcript);
  cmd->add_option("--alignment-out", args->alignment_out,
                  "Without ALIGNMENT: also write the alignment found (phones and words tiers) as a TextGrid");
  cli::add_alignment_options(*cmd, args->alignment);
}};

}  // namespace
