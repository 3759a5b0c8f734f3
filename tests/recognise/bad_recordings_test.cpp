// Named bad recordings, made in the test from a real one (EMU ae msajc003, 20 kHz, "amongst her
// friends she was considered beautiful"): each is refused with its rule and exactly its message.
// The mismatch messages come from the diagnosis pass (a garbage loop per word, an exit to the end
// after any word: spec/recognise.md, "A recording that does not say its transcript").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "fapcast/core/file_io.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/portable_random.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/recognise/speech_aligner.hpp"

namespace fapcast {
namespace {

const std::string kEmu = std::string(FAPCAST_TEST_DATA) + "/speech/emu-ae/";

struct BadRecording {
  std::string name;
  Audio audio;
  std::string rule;
  std::string message;
};

Audio take() { return read_wav(kEmu + "msajc003.wav"); }

std::vector<BadRecording> bad_recordings() {
  const Audio speech = take();
  std::vector<BadRecording> out;
  {
    Audio a{speech.sample_rate, 1, std::vector<std::int16_t>(static_cast<std::size_t>(3 * speech.sample_rate.hz), 0)};
    out.push_back({"silence", a, "no-speech", "silence.wav: no-speech: no path through the transcript fits the recording, even with words left out (another recording's text, silence or noise?)"});
  }
  {
    Audio a{speech.sample_rate, 1, std::vector<std::int16_t>(static_cast<std::size_t>(3 * speech.sample_rate.hz))};
    PortableRandom random(18);
    for (auto& s : a.samples) s = static_cast<std::int16_t>(std::lround(random.uniform(-3000.0, 3000.0)));
    out.push_back({"noise", a, "no-speech", "noise.wav: no-speech: no path through the transcript fits the recording, even with words left out (another recording's text, silence or noise?)"});
  }
  {
    Audio a = speech;
    a.samples.resize(a.samples.size() / 2);
    out.push_back({"truncated", a, "transcript-mismatch",
                   "truncated.wav: transcript-mismatch: 1.45 s: the recording diverges from the transcript at word 5 'was' "
                   "(byte 24): not found in the recording"});
  }
  {
    Audio a = speech;
    a.sample_rate = SampleRate{8000};  // the header says 8 kHz: the speech plays 2.5 times slower
    out.push_back({"header-rate-8k", a, "no-speech",
                   "header-rate-8k.wav: no-speech: no word of the transcript was found in the recording (silence, noise, "
                   "another recording?)"});
  }
  {
    Audio a = speech;
    a.sample_rate = SampleRate{44100};  // 2.2 times faster
    out.push_back({"header-rate-44k", a, "transcript-mismatch",
                   "header-rate-44k.wav: transcript-mismatch: 0.54 s: the recording diverges from the transcript at word 1 "
                   "'amongst' (byte 0): not found in the recording"});
  }
  {
    Audio a = speech;
    a.samples.resize(static_cast<std::size_t>(speech.sample_rate.hz / 20));
    out.push_back({"too-short", a, "speech-empty", "too-short.wav: speech-empty: the recording is shorter than 0.1 s"});
  }
  return out;
}

TEST(BadRecordings, EachIsRefusedWithItsRuleAndMessage) {
  SpeechAligner aligner;
  const Transcript transcript = parse_transcript(read_file(kEmu + "msajc003.txt"), "msajc003.txt");
  for (const BadRecording& b : bad_recordings()) {
    SCOPED_TRACE(b.name);
    try {
      (void)aligner.align(b.audio, transcript, b.name + ".wav");
      ADD_FAILURE() << "aligned";
    } catch (const InputError& e) {
      EXPECT_EQ(e.rule(), b.rule);
      EXPECT_EQ(std::string(e.what()), b.message);
    }
  }
}

// Without a transcript: silence, noise and a too-short recording are refused too (recognition
// hears no word in the first two).
TEST(BadRecordings, RecognitionRefusesSilenceNoiseAndTooShort) {
  SpeechAligner aligner;
  const std::vector<BadRecording> all = bad_recordings();
  const std::vector<std::pair<std::string, std::string>> expected{
      {"silence", "silence.wav: no-speech: no word was heard in the recording (silence or noise?)"},
      {"noise", "noise.wav: no-speech: no word was heard in the recording (silence or noise?)"},
      {"too-short", "too-short.wav: speech-empty: the recording is shorter than 0.1 s"}};
  for (const auto& [name, message] : expected) {
    SCOPED_TRACE(name);
    const std::string& wanted = name;  // clang 14 cannot capture a structured binding
    const auto b = std::find_if(all.begin(), all.end(), [&](const BadRecording& r) { return r.name == wanted; });
    ASSERT_NE(b, all.end());
    try {
      (void)aligner.recognise(b->audio, name + ".wav");
      ADD_FAILURE() << "recognised";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  }
}

}  // namespace
}  // namespace fapcast
