// `fapcast say "TEXT" -o OUT.fap|OUT.glb [--wav-out OUT.wav] [--voice V] [--fps N] [--expression E] ...`:
// speaks the text with espeak-ng and animates it (spec/synthesis.md). Argument parsing only.
#include "command.hpp"
#include "output_check.hpp"
#include "synthesis_cli.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/frontend/text_frontend.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>

namespace {
using namespace fapcast;

const cli::Registration reg{"say", [](CLI::App& app) {
  struct Args {
    std::string text;
    std::string wav;
    cli::SynthesisArgs synthesis;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = cli::add_synthesis_command(
      app, "say", "Speak English text (espeak-ng) and animate it: a FAP track or a glTF mesh in sync with the WAV",
      args->synthesis, [args] {
        // A .glb is a mesh for a player: its sound goes beside it unless told where.
        std::string wav = args->wav;
        if (wav.empty() && (cli::is_mesh_output(args->synthesis.output) ||
                            cli::is_rig_output(args->synthesis.output, args->synthesis.rig)))
          wav = std::filesystem::path(args->synthesis.output).replace_extension(".wav").string();
        cli::check_output_writable(wav);  // the track's output was checked before this runs
        const Speech speech = speak(args->text);
        if (speech.phones.empty()) throw std::runtime_error("say: TEXT: empty-text: nothing to say");
        // The track and its WAV appear together or not at all: the WAV is written first but
        // committed only after the track was, and the track is removed again if that fails.
        std::optional<AtomicFile> wav_file;
        if (!wav.empty()) {
          wav_file.emplace(wav);
          wav_file->write(wav_bytes(speech.audio));
        }
        args->synthesis.cues.sound_file = wav;
        args->synthesis.words = speech.words;
        cli::synthesize_to_file(args->synthesis, speech.phones, speech.audio.sample_rate,
                                  static_cast<std::int64_t>(speech.audio.samples.size()), "say: text", "fapcast say");
        if (wav_file) {
          try {
            wav_file->commit();
          } catch (...) {
            std::error_code ignored;
            std::filesystem::remove(args->synthesis.output, ignored);
            throw;
          }
        }
      });
  cmd->add_option("TEXT", args->text, "The text (UTF-8)")->required();
  cmd->add_option("--wav-out", args->wav, "Write the speech here (16-bit mono WAV; with .glb: beside it by default)");
}};

}  // namespace
