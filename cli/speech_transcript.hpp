#pragma once
// What `align` and `animate` share for recorded speech with its transcript: the --transcript FILE
// and --text TEXT options, and the forced alignment of the WAV with them (spec/recognise.md).
#include <CLI/CLI.hpp>

#include <string>

#include "fapcast/recognise/speech_alignment.hpp"

namespace fapcast::cli {

struct TranscriptArgs {
  std::string file;  // --transcript FILE
  std::string text;  // --text TEXT
  bool given() const { return !file.empty() || !text.empty(); }
};

void add_transcript_options(CLI::App& command, TranscriptArgs& args);

// Aligns the WAV at `wav` with the transcript of `args` (exactly one of its two must be given:
// else UsageError); notes and warnings (downmixed channels, low-confidence words) on standard
// error unless `quiet`.
SpeechAlignment align_recording(const std::string& wav, const TranscriptArgs& args, bool quiet);

}  // namespace fapcast::cli
