#include "speech_transcript.hpp"

#include <iostream>
#include <optional>
#include <string>

#include "command.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/core/text_input.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/frontend/espeak_language.hpp"
#include "fapcast/recognise/speech_aligner.hpp"

namespace fapcast::cli {

void add_transcript_options(CLI::App& command, TranscriptArgs& args) {
  args.file_option = command.add_option("--transcript", args.file,
                     "What the speech says, as a UTF-8 text file: its phones are found by forced alignment "
                     "(spec/recognise.md); without it or --text, what the speech says is recognised");
  args.text_option = command.add_option("--text", args.text, "What the speech says, as text (instead of --transcript FILE)");
  command.add_option("--lang", args.lang,
                     "The accent the speech is read in, as an espeak-ng language (`espeak-ng --voices`: en-gb, "
                     "en-gb-scotland, ...): espeak-ng's reading of each word in it is one more pronunciation to align "
                     "with (spec/recognise.md, \"Accents\"); default: the US dictionary's only");
}

SpeechAlignment align_recording(const std::string& wav, const TranscriptArgs& args, bool quiet) {
  if (args.file_given() && args.text_given())
    throw UsageError("give what the speech says with --transcript FILE or --text TEXT, not both");
  if (!args.lang.empty() && !espeak_language_installed(args.lang))
    throw UsageError("--lang '" + args.lang + "': not an installed espeak-ng language (espeak-ng --voices lists them)");
  const bool recognised = !args.given();
  const std::string source = args.file_given() ? args.file : "--text";
  std::optional<Transcript> transcript;
  if (!recognised)
    transcript = parse_transcript(args.file_given() ? decode_text(read_file(args.file), args.file, "transcript") : args.text,
                                  source);
  const Audio recorded = read_wav(wav);
  SpeechAligner aligner({.language = args.lang});
  SpeechAlignment found = recognised ? aligner.recognise(recorded, wav) : aligner.align(recorded, *transcript, wav);
  if (!quiet) {
    if (recorded.channels > 1)
      std::cerr << "fapcast: note: " << wav << ": " << recorded.channels << " channels downmixed to mono\n";
    if (recognised) {
      std::string heard;
      double sum = 0, seconds = 0;
      std::size_t low = 0;
      for (const SpeechWord& w : found.words) {
        heard += (heard.empty() ? "" : " ") + w.text;
        const double s = static_cast<double>(w.end_sample - w.start_sample) / static_cast<double>(found.sample_rate.hz);
        sum += w.score_per_frame * s;
        seconds += s;
        low += w.low_confidence;
      }
      std::cerr << "fapcast: note: " << wav << ": no transcript: recognised " << found.words.size() << " words, mean score "
                << (seconds > 0 ? sum / seconds : 0.0) << " per frame, " << low << " below " << kLowConfidenceScore
                << ": \"" << heard << "\"\n";
    }
    for (const SpeechWord& w : found.words)
      if (w.low_confidence)
        std::cerr << "fapcast: warning: " << wav << ": "
                  << static_cast<double>(w.start_sample) / static_cast<double>(found.sample_rate.hz) << " s: the word '"
                  << w.text << "'" << (recognised ? "" : " (byte " + std::to_string(w.byte_offset) + " of " + source + ")")
                  << (recognised ? " was heard with low confidence" : " matches the recording poorly") << " (score "
                  << w.score_per_frame << " per frame)\n";
  }
  return found;
}

}  // namespace fapcast::cli
