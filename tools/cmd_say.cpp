// `fapcast say "TEXT" -o OUT.fap [--wav OUT.wav] [--voice V] [--fps N] ...`: speaks the text with
// espeak-ng and animates it (spec/synthesis.md). Argument parsing only.
#include "command.hpp"
#include "synthesis_cli.hpp"

#include "fapcast/synth/mono_audio.hpp"
#include "fapcast/synth/text_frontend.hpp"

#include <memory>
#include <stdexcept>

namespace {
using namespace fapcast;

const tools::Registration reg{"20-say", [](CLI::App& app) {
  struct Args {
    std::string text;
    std::string wav;
    tools::SynthesisArgs synthesis;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("say", "Speak English text (espeak-ng) and animate it: a FAP track in sync "
                                        "with the WAV");
  cmd->add_option("TEXT", args->text, "The text (UTF-8)")->required();
  cmd->add_option("--wav", args->wav, "Write the speech here (16-bit mono WAV)");
  tools::add_synthesis_options(cmd, args->synthesis);
  cmd->callback([args] {
    tools::check_animation_output("say", args->synthesis);
    const synth::Speech speech = synth::speak(args->text);
    if (speech.phones.empty()) throw std::runtime_error("say: TEXT: empty-text: nothing to say");
    if (!args->wav.empty()) synth::write_wav(args->wav, speech.audio);
    tools::synthesize_to_file(args->synthesis, speech.phones, speech.audio.sample_rate_hz,
                              static_cast<std::int64_t>(speech.audio.samples.size()), "say: text", "fapcast say");
  });
}};

}  // namespace
