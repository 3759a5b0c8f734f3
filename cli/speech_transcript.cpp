#include "speech_transcript.hpp"

#include <iostream>

#include "command.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/core/text_input.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/recognise/speech_aligner.hpp"

namespace fapcast::cli {

void add_transcript_options(CLI::App& command, TranscriptArgs& args) {
  command.add_option("--transcript", args.file,
                     "What the speech says, as a UTF-8 text file: its phones are found by forced alignment "
                     "(spec/recognise.md)");
  command.add_option("--text", args.text, "What the speech says, as text (instead of --transcript FILE)");
}

SpeechAlignment align_recording(const std::string& wav, const TranscriptArgs& args, bool quiet) {
  if (args.file.empty() == args.text.empty())
    throw UsageError("give what the speech says with --transcript FILE or --text TEXT (one of them)");
  const std::string source = args.file.empty() ? "--text" : args.file;
  const std::string text = args.file.empty() ? args.text : decode_text(read_file(args.file), args.file, "transcript");
  const Transcript transcript = parse_transcript(text, source);
  const Audio recorded = read_wav(wav);
  SpeechAligner aligner;
  SpeechAlignment found = aligner.align(recorded, transcript, wav);
  if (!quiet) {
    if (recorded.channels > 1)
      std::cerr << "fapcast: note: " << wav << ": " << recorded.channels << " channels downmixed to mono\n";
    for (const SpeechWord& w : found.words)
      if (w.low_confidence)
        std::cerr << "fapcast: warning: " << wav << ": "
                  << static_cast<double>(w.start_sample) / static_cast<double>(found.sample_rate.hz) << " s: the word '"
                  << w.text << "' (byte " << w.byte_offset << " of " << source
                  << ") matches the recording poorly (score " << w.score_per_frame << " per frame)\n";
  }
  return found;
}

}  // namespace fapcast::cli
