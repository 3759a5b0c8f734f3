// `fapcast animate --wav IN.wav --align IN.TextGrid|IN.lab -o OUT.fap [--voice V] ...`: animates
// recorded speech from its phone alignment (spec/synthesis.md). Argument parsing only.
#include "command.hpp"
#include "synthesis_cli.hpp"

#include "fapcast/corpus/alignment_file.hpp"
#include "fapcast/corpus/alignment_phones.hpp"
#include "fapcast/core/mono_audio.hpp"
#include "fapcast/core/file_io.hpp"

#include <iostream>
#include <memory>
#include <stdexcept>

namespace {
using namespace fapcast;

// An alignment may end up to 20 ms after its audio (rounding, a trailing pause) and is cut there.
constexpr std::int64_t kToleranceMs = 20;

const cli::Registration reg{"21-animate", [](CLI::App& app) {
  struct Args {
    std::string wav;
    std::string align;
    std::string tier;
    std::string phone_set;
    cli::SynthesisArgs synthesis;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = cli::add_synthesis_command(
      app, "animate", "Animate recorded speech from its WAV and phone alignment (TextGrid, .lab, .phn, .mlf, .par, Gentle .json)",
      args->synthesis, [args] {
        AlignmentFileOptions options;
        if (!args->tier.empty()) options.tier = args->tier;
        if (!args->phone_set.empty()) {
          options.label_set = label_set_from_name(args->phone_set);
          if (!options.label_set)
            throw cli::UsageError("animate: --phone-set '" + args->phone_set +
                                  "' is none of arpabet, timit, ipa, sampa, emu-ae");
        }
        const MonoAudio audio = read_wav(args->wav);
        options.sample_rate_hz = audio.sample_rate_hz;
        options.audio_seconds = static_cast<double>(audio.samples.size()) / audio.sample_rate_hz;
        const AlignmentFile alignment = read_alignment_file(read_file(args->align), args->align, options);
        if (!args->synthesis.quiet) {
          if (audio.source_channels > 1)
            std::cerr << "fapcast: note: " << args->wav << ": " << audio.source_channels << " channels downmixed to mono\n";
          for (const std::string& note : alignment.notes) std::cerr << "fapcast: note: " << args->align << ": " << note << "\n";
        }
        const auto samples = static_cast<std::int64_t>(audio.samples.size());
        auto phones = timed_phones(alignment.segments, audio.sample_rate_hz);
        if (!phones.empty() && phones.back().end_sample < samples && !args->synthesis.quiet)
          std::cerr << "fapcast: warning: " << args->align << " ends before " << args->wav
                    << "; the rest is animated as silence\n";
        phones = fit_phones_to_audio(std::move(phones), samples,
                                            kToleranceMs * audio.sample_rate_hz / 1000, args->align);
        cli::synthesize_to_file(args->synthesis, phones, audio.sample_rate_hz, samples, args->align,
                                  "fapcast animate");
      });
  cmd->add_option("--wav", args->wav, "The speech (WAV; two or more channels are downmixed): the timeline")->required();
  cmd->add_option("--align", args->align,
                  "Its phone alignment: Praat TextGrid (text, binary, chronological), HTK .lab/.mlf, ESPS/Festival .lab, "
                  "TIMIT .phn, BAS .par, Gentle .json (spec/corpus.md)")->required();
  cmd->add_option("--tier", args->tier, "The alignment's phone tier (default: found by name, then by its labels)");
  cmd->add_option("--phone-set", args->phone_set,
                  "The labels' symbol set: arpabet, timit, ipa, sampa, emu-ae (default: the set that reads them)");
}};

}  // namespace
