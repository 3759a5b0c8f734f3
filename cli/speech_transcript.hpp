#pragma once
// What `align` and `animate` share for recorded speech: the --transcript FILE, --text TEXT and
// --lang options, and the forced alignment of the WAV with them, or its recognition without them
// (spec/recognise.md).
#include <CLI/CLI.hpp>

#include <string>

#include "fapcast/recognise/speech_alignment.hpp"

namespace fapcast::cli {

struct TranscriptArgs {
  std::string file;  // --transcript FILE
  std::string text;  // --text TEXT
  std::string lang;  // --lang: the accent the transcript is read in (AlignerSettings::language)
  // Whether each option was on the command line: `--text ""` asks for forced alignment (and is
  // refused as an empty transcript), it does not fall back to recognition.
  const CLI::Option* file_option = nullptr;
  const CLI::Option* text_option = nullptr;
  bool file_given() const { return file_option != nullptr && file_option->count() > 0; }
  bool text_given() const { return text_option != nullptr && text_option->count() > 0; }
  bool given() const { return file_given() || text_given(); }
};

void add_transcript_options(CLI::App& command, TranscriptArgs& args);

// Aligns the WAV at `wav` with the transcript of `args` (at most one of its two may be given,
// --lang an installed espeak-ng language: else UsageError), or recognises what it says when neither is; notes and warnings (downmixed
// channels, the words recognised and their confidence, low-confidence words) on standard error
// unless `quiet`.
SpeechAlignment align_recording(const std::string& wav, const TranscriptArgs& args, bool quiet);

}  // namespace fapcast::cli
