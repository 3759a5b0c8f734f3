// `fapcast say TEXT|- [--text-file FILE] [--lang CODE] [--espeak-variant V] [--ssml] -o OUT ...`:
// speaks the text with espeak-ng and animates it (spec/synthesis.md). Argument parsing only.
#include "command.hpp"
#include "output_check.hpp"
#include "streamed_fap_track.hpp"
#include "synthesis_cli.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/core/text_input.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/frontend/espeak_language.hpp"
#include "fapcast/frontend/text_frontend.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <stdexcept>

namespace {
using namespace fapcast;

// Standard input whole, as bytes.
std::string read_stdin() {
  std::cin >> std::noskipws;
  std::string bytes{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
  if (std::cin.bad()) throw std::runtime_error("say: <stdin>: read failed");
  return bytes;
}

const cli::Registration say_command{"say", [](CLI::App& app) {
  struct Args {
    std::string text;
    std::string text_file;
    std::string language = std::string(kDefaultLanguage);
    std::string variant;
    bool ssml = false;
    std::string wav;
    cli::SynthesisArgs synthesis;
    CLI::Option* piece_seconds = nullptr;  // --piece-seconds, to tell whether it was given
  };
  auto args = std::make_shared<Args>();
  auto* cmd = cli::add_synthesis_command(
      app, "say", "Speak text in any espeak-ng language (or SSML) and animate it: a FAP track or a glTF mesh in sync with the WAV",
      args->synthesis, [args] {
        if (args->text.empty() == args->text_file.empty())
          throw cli::UsageError("say: give the text as TEXT, as - (standard input) or with --text-file FILE (one of them)");
        // Pieces are for a FAP track: a mesh, a rig or --vmc takes the whole text at once, so a
        // piece length asked for would be ignored (and the memory it bounds not bounded).
        if (args->piece_seconds->count() > 0 && !cli::is_streamed_output(args->synthesis))
          throw cli::UsageError("say: --piece-seconds applies to a FAP track (-o .fap, .fba, .json or .bvh, without "
                                "--rig or --vmc); " +
                                (args->synthesis.output.empty() ? std::string("mouth cues alone have no track")
                                                                : "'" + args->synthesis.output + "' is made from the whole text at once"));
        // Listing espeak-ng's voices reads every voice file (5 ms): only for a language or
        // variant the user named (the default, en-us, is the front-end's own).
        if (args->language != kDefaultLanguage && !espeak_language_installed(args->language))
          throw cli::UsageError("say: --lang '" + args->language + "': not an installed espeak-ng language (espeak-ng --voices lists them)");
        const auto variants = args->variant.empty() ? std::vector<std::string>{} : espeak_variants();
        if (!args->variant.empty() && std::find(variants.begin(), variants.end(), args->variant) == variants.end())
          throw cli::UsageError("say: --espeak-variant '" + args->variant +
                                "': not an installed espeak-ng variant (espeak-ng --voices=variant lists them)");
        // A .glb is a mesh for a player: its sound goes beside it unless told where.
        std::string wav = args->wav;
        if (wav.empty() && (cli::is_mesh_output(args->synthesis.output) ||
                            cli::is_rig_output(args->synthesis.output, args->synthesis.rig)))
          wav = std::filesystem::path(args->synthesis.output).replace_extension(".wav").string();
        cli::check_output_writable(wav);  // the track's output was checked before this runs
        SpeakOptions options{.language = args->language, .variant = args->variant, .ssml = args->ssml};
        std::string text = args->text;
        if (!args->text_file.empty()) {
          options.source = args->text_file;
          text = decode_text(read_file(args->text_file), args->text_file, "text");
        } else if (args->text == "-") {
          options.source = "<stdin>";
          text = decode_text(read_stdin(), options.source, "text");
        }
        // The speech is made chunk by chunk (at sentence ends, kChunkBytes): each chunk's audio
        // goes straight into the WAV's temporary file and only the timing is kept, so memory
        // does not grow with the sound (spec/phones.md, "Memory"). A FAP track is made piece by
        // piece as the timing comes, cut in pauses, and written as it goes (streamed_fap_track.hpp,
        // spec/synthesis.md "Long texts"); a mesh or a rig takes the whole timing at the end.
        // The track and its WAV appear together or not at all.
        std::optional<AtomicFile> wav_file;
        std::optional<WavWriter> wav_writer;
        if (!wav.empty()) wav_file.emplace(wav);
        cli::SynthesisArgs& synthesis = args->synthesis;
        const bool streamed = cli::is_streamed_output(synthesis) && synthesis.piece_seconds > 0;
        std::optional<cli::StreamedFapTrack> track;
        std::vector<TimedPhone> cue_phones;  // every phone, for --cues-out (the pieces forget theirs)
        Speech speech;
        std::int64_t samples = 0;
        speak_chunks(text, options, [&](Speech&& part) {
          const std::span<const std::int16_t> audio = part.audio.samples;  // left there: the next chunk's buffer
          const SampleRate rate = part.audio.sample_rate;
          const std::size_t before = speech.phones.size();
          if (!append_timing(speech, std::move(part), samples)) return;
          if (wav_file) {
            if (!wav_writer) wav_writer.emplace(*wav_file, rate);
            wav_writer->append(audio);
          }
          samples += static_cast<std::int64_t>(audio.size());
          if (!streamed) return;
          if (!synthesis.cues.output.empty()) {
            if (before > 0) cue_phones.back() = speech.phones[before - 1];  // a silence the chunk continued
            cue_phones.insert(cue_phones.end(), speech.phones.begin() + static_cast<std::ptrdiff_t>(before),
                              speech.phones.end());
          }
          speech.events.clear();  // neither is needed for a FAP track
          speech.words.clear();
          if (!track) track.emplace(synthesis, rate, "say: text", "fapcast say");
          track->add(speech.phones);
        });
        if (!track && speech.phones.empty()) throw std::runtime_error("say: " + options.source + ": empty-text: nothing to say");
        if (wav_writer) wav_writer->finish();
        synthesis.cues.sound_file = wav;
        if (!streamed) {
          synthesis.words = speech.words;
          cli::synthesize_to_file(synthesis, speech.phones, speech.audio.sample_rate, samples, "say: text", "fapcast say");
          if (wav_file) {
            try {
              wav_file->commit();
            } catch (...) {
              std::error_code ignored;
              std::filesystem::remove(synthesis.output, ignored);
              throw;
            }
          }
          return;
        }
        const std::string cues = cli::write_cue_output(synthesis.cues, cue_phones, speech.audio.sample_rate, samples);
        track->finish(speech.phones, samples);
        if (wav_file)
          commit_together({&track->output(), &*wav_file});
        else
          track->output().commit();
        std::cout << track->summary(cues) << "\n";
      });
  cmd->add_option("TEXT", args->text, "The text (UTF-8); - reads it from standard input");
  cmd->add_option("--text-file", args->text_file, "Read the text from this file (UTF-8, or UTF-16 with a BOM; any length)");
  cmd->add_option("--lang", args->language,
                  "espeak-ng language code, as `espeak-ng --voices` lists it (ru, de, cmn, en-gb, ...)")
      ->capture_default_str();
  cmd->add_option("--espeak-variant", args->variant,
                  "espeak-ng voice variant, as `espeak-ng --voices=variant` lists it by file (f2, m3, klatt, ...)");
  cmd->add_flag("--ssml", args->ssml, "The text is SSML: espeak-ng parses the markup (<break>, <prosody>, ...)");
  args->piece_seconds = cmd->add_option("--piece-seconds", args->synthesis.piece_seconds,
                  "A FAP track is made and written in pieces of about this much speech, each ending in a pause "
                  "(bounded memory for any length); 0: the whole text at once. FAP tracks only (.glb and rigs "
                  "are made whole)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--wav-out", args->wav, "Write the speech here (16-bit mono WAV; with .glb: beside it by default)");
}};

}  // namespace
