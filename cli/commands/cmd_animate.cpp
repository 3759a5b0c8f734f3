// `fapcast animate SPEECH.wav ALIGNMENT.TextGrid|.lab -o OUT.fap [--voice V] ...`: animates
// recorded speech from its phone alignment (spec/synthesis.md). Argument parsing only.
#include "command.hpp"
#include "file_extension.hpp"
#include "synthesis_cli.hpp"

#include "fapcast/corpus/alignment_phones.hpp"
#include "fapcast/corpus/lab_file.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/corpus/textgrid.hpp"
#include "fapcast/core/file_io.hpp"

#include <iostream>
#include <memory>
#include <stdexcept>

namespace {
using namespace fapcast;

// An alignment may end up to 20 ms after its audio (rounding, a trailing pause) and is cut there.
constexpr std::int64_t kToleranceMs = 20;

Alignment read_alignment(const std::string& path) {
  const std::string ext = cli::lower_extension(path);
  const std::string bytes = read_file(path);
  if (ext == ".textgrid") return read_textgrid(bytes, path);
  const LabFile lab = read_lab(bytes, path);
  Alignment a;
  a.tiers.push_back(to_tier(lab, "phones"));
  a.end_s = a.tiers.back().end_s;
  return a;
}

const cli::Registration reg{"animate", [](CLI::App& app) {
  struct Args {
    std::string wav;
    std::string align;
    cli::SynthesisArgs synthesis;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = cli::add_synthesis_command(
      app, "animate", "Animate recorded speech from its WAV and phone alignment (TextGrid or HTK/MOCHA .lab)",
      args->synthesis, [args] {
        const std::string ext = cli::lower_extension(args->align);
        if (ext != ".textgrid" && ext != ".lab")
          throw cli::UsageError("animate: alignment '" + args->align + "' must end in .TextGrid or .lab");
        const Audio audio = read_mono_wav(args->wav);
        const Alignment alignment = read_alignment(args->align);
        const LabelTier* tier = phone_tier(alignment);
        if (tier == nullptr || tier->intervals.empty())
          throw std::runtime_error(args->align + ": no-phone-tier: the alignment has no phone intervals");
        const auto samples = static_cast<std::int64_t>(audio.samples.size());
        auto phones = phones_from_tier(*tier, audio.sample_rate, args->align);
        if (!phones.empty() && phones.back().end_sample < samples && !args->synthesis.quiet)
          std::cerr << "fapcast: warning: " << args->align << " ends before " << args->wav
                    << "; the rest is animated as silence\n";
        phones = fit_phones_to_audio(std::move(phones), samples,
                                            kToleranceMs * audio.sample_rate.hz / 1000, args->align);
        cli::synthesize_to_file(args->synthesis, phones, audio.sample_rate, samples, args->align,
                                  "fapcast animate");
      });
  cmd->add_option("SPEECH", args->wav, "The speech (mono WAV): the timeline")->required();
  cmd->add_option("ALIGNMENT", args->align, "Its phone alignment: .TextGrid or .lab")->required();
}};

}  // namespace
