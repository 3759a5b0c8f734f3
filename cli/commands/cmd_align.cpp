// `fapcast align SPEECH.wav [--transcript FILE | --text TEXT] [--lang L] -o OUT.TextGrid [-q]`: the phones and
// words of recorded speech found by forced alignment to its transcript, or by recognition without
// one, as a TextGrid (spec/recognise.md).
// Argument parsing only.
#include "command.hpp"
#include "file_extension.hpp"
#include "output_check.hpp"
#include "speech_transcript.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/corpus/textgrid.hpp"

#include <cstdio>
#include <memory>
#include <string>

namespace {
using namespace fapcast;

const cli::Registration align_command{"align", [](CLI::App& app) {
  struct Args {
    std::string wav;
    cli::TranscriptArgs transcript;
    std::string output;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("align", "Find the phones and words of recorded speech, from its transcript or by recognition (a TextGrid)");
  cmd->add_option("SPEECH", args->wav, "The speech (WAV, any rate 8-192 kHz; two or more channels are downmixed)")
      ->required();
  cli::add_transcript_options(*cmd, args->transcript);
  cmd->add_option("-o,--output", args->output, "The alignment: OUT.TextGrid (tiers phones and words)")->required();
  cmd->add_flag("-q,--quiet", args->quiet, "No progress on standard error");
  cmd->callback([args] {
    if (cli::lower_extension(args->output) != ".textgrid")
      throw cli::UsageError("align: -o writes a .TextGrid, not '" + args->output + "'");
    cli::check_output_writable(args->output);  // before the recording is read and aligned
    const SpeechAlignment found = cli::align_recording(args->wav, args->transcript, args->quiet);
    write_file_atomically(args->output, write_textgrid(to_alignment(found)));
    std::size_t phones = 0, pauses = 0;
    for (const SpeechSegment& s : found.segments) (s.kind == SpeechSegmentKind::phone ? phones : pauses) += 1;
    std::printf("%s: %zu words, %zu phones, %zu pauses and noises in %.2f s\n", args->output.c_str(),
                found.words.size(), phones, pauses,
                static_cast<double>(found.samples) / static_cast<double>(found.sample_rate.hz));
  });
}};

}  // namespace
