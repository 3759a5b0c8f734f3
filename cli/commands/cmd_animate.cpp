// `fapcast animate SPEECH.wav ALIGNMENT -o OUT.fap [--voice V] [--tier T] [--phone-set S] ...`: animates
// recorded speech from its phone alignment (spec/synthesis.md); or, with `--transcript FILE` or
// `--text TEXT` instead of the alignment, from the phones the forced aligner finds in it, or with
// neither, from the phones of the words recognised in it (spec/recognise.md). Argument parsing only.
#include "command.hpp"
#include "file_extension.hpp"
#include "speech_transcript.hpp"
#include "synthesis_cli.hpp"

#include "fapcast/corpus/alignment_file.hpp"
#include "fapcast/corpus/alignment_phones.hpp"
#include "fapcast/core/downmix.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/corpus/textgrid.hpp"
#include "fapcast/recognise/speech_alignment.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace {
using namespace fapcast;

// An alignment may end up to 20 ms after its audio (rounding, a trailing pause) and is cut there.
constexpr std::int64_t kToleranceMs = 20;

template <typename Args>
void animate_from_transcript(const Args& args) {
  if (!args.alignment_out.empty() && cli::lower_extension(args.alignment_out) != ".textgrid")
    throw cli::UsageError("animate: --alignment-out writes a .TextGrid, not '" + args.alignment_out + "'");
  const SpeechAlignment found = cli::align_recording(args.wav, args.transcript, args.synthesis.quiet);
  if (!args.alignment_out.empty()) write_file_atomically(args.alignment_out, write_textgrid(to_alignment(found)));
  const std::vector<TimedPhone> phones = timed_phones(found);
  cli::synthesize_to_file(args.synthesis, phones, found.sample_rate, found.samples, args.wav, "fapcast animate");
}

const cli::Registration reg{"animate", [](CLI::App& app) {
  struct Args {
    std::string wav;
    std::string align;
    std::string tier;
    std::string phone_set;
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
        if (args->align.empty()) {
          if (!args->tier.empty() || !args->phone_set.empty())
            throw cli::UsageError("animate: --tier and --phone-set read an ALIGNMENT file");
          animate_from_transcript(*args);
          return;
        }
        AlignmentFileOptions options;
        if (!args->tier.empty()) options.tier = args->tier;
        if (!args->phone_set.empty()) {
          options.label_set = label_set_from_name(args->phone_set);
          if (!options.label_set)
            throw cli::UsageError("animate: --phone-set '" + args->phone_set +
                                  "' is none of arpabet, timit, ipa, sampa, emu-ae, mocha");
        }
        const Audio recorded = read_wav(args->wav);
        const Audio audio = downmix_to_mono(recorded);
        const auto samples = audio.instants();
        options.sample_rate = audio.sample_rate;
        options.utterance = std::filesystem::path(args->wav).stem().string();  // an MLF's entry
        options.audio_seconds = static_cast<double>(samples) / static_cast<double>(audio.sample_rate.hz);
        const AlignmentFile alignment = read_alignment_file(read_file(args->align), args->align, options);
        if (!args->synthesis.quiet) {
          if (recorded.channels > 1)
            std::cerr << "fapcast: note: " << args->wav << ": " << recorded.channels << " channels downmixed to mono\n";
          for (const std::string& note : alignment.notes) std::cerr << "fapcast: note: " << args->align << ": " << note << "\n";
        }
        auto phones = timed_phones(alignment.segments, audio.sample_rate, args->align);
        if (!phones.empty() && phones.back().end_sample < samples && !args->synthesis.quiet)
          std::cerr << "fapcast: warning: " << args->align << " ends before " << args->wav
                    << "; the rest is animated as silence\n";
        phones = fit_phones_to_audio(std::move(phones), samples,
                                            kToleranceMs * audio.sample_rate.hz / 1000, args->align);
        cli::synthesize_to_file(args->synthesis, phones, audio.sample_rate, samples, args->align,
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
  cmd->add_option("--tier", args->tier, "The alignment's phone tier (default: found by name, then by its labels)");
  cmd->add_option("--phone-set", args->phone_set,
                  "The labels' symbol set: arpabet, timit, ipa, sampa, emu-ae, mocha (default: the set that reads them)");
}};

}  // namespace
