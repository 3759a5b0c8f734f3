#pragma once
// Forced alignment (a recording and its transcript -> timed phones and words) and recognition (a
// recording alone -> the words heard, then aligned the same way), with pocketsphinx and its en-us
// model (Debian pocketsphinx-en-us). spec/recognise.md says how and how well.
#include <memory>
#include <string>

#include "fapcast/recognise/speech_alignment.hpp"
#include "fapcast/recognise/transcript.hpp"
#include "fapcast/core/audio.hpp"

namespace fapcast {

struct AlignerSettings {
  // A second pass over whole dictionary words places the word edges with full cross-word
  // triphones: +2.3 points of boundaries within 25 ms, half the speed (spec/recognise.md).
  bool word_edges = false;
  // Feature frames per second of the phone pass: 200 (5 ms frames, Gaussian scores every second
  // frame: the default) or 100 (the model's own rate, every frame scored). Else invalid_argument.
  int frames_per_second = 200;
  // A recording of 8 s or more is cut at its pauses and aligned piece by piece, in time linear
  // in its length (spec/recognise.md, "Long recordings"); false aligns it in one piece (the
  // comparison of tests/bench/speech_aligner_bench.cpp).
  bool in_pieces = true;
  // The accent the transcript is read in: an espeak-ng language (`espeak-ng --voices`: "en-gb").
  // Each word gets espeak-ng's reading of the transcript in it (weak forms, linking r, in
  // context) as one more pronunciation variant where it differs from the dictionary's (CMUdict,
  // US English). Empty (the default): the dictionary's variants only. An unknown language:
  // invalid_argument.
  std::string language{};
  // Each function word also gets its weak forms where the dictionary lacks them ("for" as F AH,
  // F AH R before a vowel: spec/recognise.md, "Weak forms").
  bool weak_forms = true;
};

class SpeechAligner {
 public:
  // Opens the model (decoders are created on first use). Throws std::runtime_error when the
  // pocketsphinx model is not installed.
  explicit SpeechAligner(const AlignerSettings& settings = {});
  ~SpeechAligner();
  SpeechAligner(const SpeechAligner&) = delete;
  SpeechAligner& operator=(const SpeechAligner&) = delete;

  // Aligns `speech` (any rate 8,000..192,000 Hz, any channel count: mixed to mono) with what it
  // says. Throws InputError with source `source` and rule
  //  - "speech-empty" for audio under 0.1 s,
  //  - "transcript-mismatch" when the recording does not say the transcript: the message names
  //    the first word not found in it, its byte offset in the transcript and the time where the
  //    recording diverges ("take.wav: 1.23 s: transcript-mismatch: word 4 'hard' (byte 9) ..."),
  //  - "no-speech" when nothing in the recording sounds like speech (silence, noise),
  //  - "low-confidence" when every word was placed but the recording matches its phones poorly
  //    overall (a wrong sample rate in the WAV header, another language).
  SpeechAlignment align(const Audio& speech, const Transcript& transcript, const std::string& source);

  // Recognises what `speech` says: the words the en-us word 3-gram finds (fast beams), then their
  // phones by the forced alignment above, each word's edges kept where the recogniser put them.
  // Words are dictionary words (byte_offset 0), each with its score and low_confidence mark.
  // Throws InputError "speech-empty" and "sample-rate" as align does, and "no-speech" when no
  // word is heard (silence, noise).
  SpeechAlignment recognise(const Audio& speech, const std::string& source);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fapcast
