// The espeak-ng front-end: timelines are contiguous and in samples, closures precede releases
// and sit where the energy drops, and every input class has a defined outcome.
#include "fapcast/frontend/text_frontend.hpp"
#include "fapcast/core/wav_file.hpp"

#include <gtest/gtest.h>

#include "fapcast/core/input_error.hpp"

#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <thread>

namespace fapcast {
namespace {

double rms(const std::vector<std::int16_t>& s, std::int64_t begin, std::int64_t end) {
  double sum = 0;
  for (std::int64_t i = begin; i < end; ++i) sum += double(s[i]) * s[i];
  return std::sqrt(sum / double(std::max<std::int64_t>(1, end - begin)));
}

void expect_contiguous(const Speech& speech) {
  ASSERT_FALSE(speech.phones.empty());
  ASSERT_EQ(speech.events.size(), speech.phones.size());
  EXPECT_EQ(speech.phones.front().start_sample, 0);
  EXPECT_EQ(speech.phones.back().end_sample, static_cast<std::int64_t>(speech.audio.samples.size()));
  for (std::size_t i = 0; i < speech.phones.size(); ++i) {
    const TimedPhone& p = speech.phones[i];
    EXPECT_LT(p.start_sample, p.end_sample) << i;
    EXPECT_LE(p.start_sample, speech.events[i].release_sample) << i;
    if (i > 0) {
      EXPECT_EQ(p.start_sample, speech.phones[i - 1].end_sample) << i;
    }
    if (speech.events[i].word != kNoWord) {
      EXPECT_LT(static_cast<std::size_t>(speech.events[i].word), speech.words.size());
    }
  }
}

std::string arpabet_of(const Speech& s) {
  std::string out;
  for (const auto& p : s.phones) out += std::string(arpabet(p.phone)) + " ";
  return out;
}

TEST(TextFrontend, APupGivesPhonesWordsAndEspeakRate) {
  const Speech s = speak("a pup");
  EXPECT_EQ(s.audio.sample_rate.hz, 22050);
  expect_contiguous(s);
  EXPECT_EQ(arpabet_of(s), "AX P AH P SIL ");  // a# is a schwa, V the strut vowel
  ASSERT_EQ(s.words.size(), 2u);
  EXPECT_EQ(s.words[0].text, "a");
  EXPECT_EQ(s.words[1].text, "pup");
  EXPECT_EQ(s.words[1].byte_offset, 2u);
  EXPECT_LE(s.words[0].end_sample, s.words[1].start_sample);
}

// espeak-ng synthesises an /l/ after a vowel before a pause or a voiceless fricative inside the
// vowel's segment: its phoneme event has the next phone's sample. The phone is kept, in the later
// half of the vowel's segment ("yourself" Y AO S EH L F, "all" AO L), not dropped.
TEST(TextFrontend, APhoneEspeakGivesNoSamplesTakesTheLaterHalfOfTheOneBefore) {
  for (const auto& [text, phones] : {std::pair<const char*, const char*>{"yourself", "Y AO S EH L F SIL "},
                                     {"all", "AO L SIL "}, {"involved", "IH N V AA L V D SIL "}}) {
    const Speech s = speak(text);
    expect_contiguous(s);
    EXPECT_EQ(arpabet_of(s), phones) << text;
    for (std::size_t i = 1; i < s.phones.size(); ++i) {
      if (s.phones[i].phone != Phone::L) continue;
      const TimedPhone& vowel = s.phones[i - 1];
      const TimedPhone& l = s.phones[i];
      EXPECT_TRUE(is_vowel(vowel.phone)) << text;
      EXPECT_EQ(l.start_sample, vowel.start_sample + (l.end_sample - vowel.start_sample) / 2) << text;
      EXPECT_EQ(s.events[i].event_sample, l.end_sample) << text;  // where espeak-ng put it
    }
  }
}

class Closures : public testing::TestWithParam<const char*> {};

// In "a pup" and "a bob" the lips close after the schwa: the stop's segment must start
// before its release, where the audio energy drops: quiet just after the onset (below a quarter
// of the previous phone's peak), half as loud again just before it (5 ms tolerance; a voiced
// closure keeps a voice bar, so its drop is smaller than a voiceless one's).
TEST_P(Closures, ClosurePrecedesReleaseWhereEnergyDrops) {
  const Speech s = speak(GetParam());
  expect_contiguous(s);
  const std::int64_t ms10 = s.audio.sample_rate.hz / 100;
  const std::int64_t ms5 = ms10 / 2;
  int closures = 0;
  for (std::size_t i = 1; i < s.phones.size(); ++i) {
    const TimedPhone& p = s.phones[i];
    const TimedPhone& previous = s.phones[i - 1];
    if (!has_closure(p.phone) || previous.phone == Phone::SIL) continue;
    ++closures;
    EXPECT_LT(p.start_sample, s.events[i].release_sample) << i;
    EXPECT_LE(p.start_sample, s.events[i].event_sample + ms5) << i;
    double peak = 0;
    for (std::int64_t c = previous.start_sample; c + ms10 <= p.start_sample; c += ms10 / 4) {
      peak = std::max(peak, rms(s.audio.samples, c, c + ms10));
    }
    // 10 ms windows 5 ms either side of the onset (a 60 fps frame is 16.7 ms).
    const double before = rms(s.audio.samples, p.start_sample - ms5 - ms10, p.start_sample - ms5);
    const double after = rms(s.audio.samples, p.start_sample + ms5, p.start_sample + ms5 + ms10);
    EXPECT_LT(after, 0.25 * peak) << GetParam() << " phone " << i;
    EXPECT_GT(before, 1.5 * after) << GetParam() << " phone " << i;
  }
  EXPECT_EQ(closures, 2);
}
INSTANTIATE_TEST_SUITE_P(Words, Closures, testing::Values("a pup", "a bob"));

TEST(TextFrontend, VoicelessClosureStartsWellBeforeEspeaksRelease) {
  const Speech s = speak("a pup");
  const TimedPhone& p = s.phones[1];
  ASSERT_EQ(p.phone, Phone::P);
  // espeak-ng's event is at the burst; the silent closure before it is tens of milliseconds.
  EXPECT_GT(s.events[1].event_sample - p.start_sample, s.audio.sample_rate.hz / 50);
}

TEST(FindClosure, SyntheticStepHasItsOnsetAtTheStep) {
  // 100 ms tone, 60 ms silence, 50 ms tone: the closure spans the silence.
  const int rate = 20000;
  std::vector<std::int16_t> s;
  for (int i = 0; i < 2000; ++i) s.push_back(static_cast<std::int16_t>(8000 * std::sin(i * 0.3)));
  s.resize(3200, 0);
  for (int i = 0; i < 1000; ++i) s.push_back(static_cast<std::int16_t>(8000 * std::sin(i * 0.3)));
  const Closure c = find_closure(s, SampleRate{rate}, 0, 3200, 4200);
  EXPECT_NEAR(static_cast<double>(c.onset_sample), 2000, 100);
  EXPECT_NEAR(static_cast<double>(c.release_sample), 3200, 100);
  // No silence: the closure is the event.
  const std::vector<std::int16_t> tone(s.begin(), s.begin() + 2000);
  EXPECT_EQ(find_closure(tone, SampleRate{rate}, 0, 1000, 2000), (Closure{1000, 1000}));
}

TEST(TextFrontend, EmptyAndWhitespaceGiveEmptySpeech) {
  for (const char* text : {"", " ", "\n\t \r\n"}) {
    const Speech s = speak(text);
    EXPECT_TRUE(s.audio.samples.empty());
    EXPECT_TRUE(s.phones.empty());
    EXPECT_TRUE(s.words.empty());
    EXPECT_EQ(s.audio.sample_rate.hz, 22050);
  }
}

TEST(TextFrontend, NothingSpeakableGivesOnlySilence) {
  const Speech s = speak("...");
  expect_contiguous(s);
  for (const auto& p : s.phones) EXPECT_EQ(p.phone, Phone::SIL);
  EXPECT_TRUE(s.words.empty());
}

TEST(TextFrontend, EmojiIsReadByName) {
  const Speech s = speak("ok \xF0\x9F\x98\x80");  // U+1F600
  expect_contiguous(s);
  ASSERT_GE(s.words.size(), 2u);
  EXPECT_EQ(s.words[1].text, "\xF0\x9F\x98\x80");
}

struct BadText { std::string text; std::string message; };
class RejectedText : public testing::TestWithParam<BadText> {};
TEST_P(RejectedText, IsRefusedWithOffsetAndRule) {
  try {
    speak(GetParam().text);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), GetParam().message);
  }
}
INSTANTIATE_TEST_SUITE_P(Cases, RejectedText, testing::Values(
    BadText{"ab\x01", "text: byte 2: control-character: U+1 (decimal)"},
    BadText{"a\x7f", "text: byte 1: control-character: U+127 (decimal)"},
    BadText{"a\xff", "text: byte 1: invalid-utf8: bad lead byte"},
    BadText{"\xc3", "text: byte 0: invalid-utf8: truncated sequence"},
    BadText{"\xc0\xaf", "text: byte 0: invalid-utf8: overlong encoding"},
    BadText{"\xed\xa0\x80", "text: byte 0: invalid-utf8: not a scalar value"},
    BadText{"x\xc3(", "text: byte 1: invalid-utf8: bad continuation byte"},
    // A bad byte deep in a long text is found before anything is synthesised.
    BadText{std::string(100 * 1024, 'a') + "\x01",
            "text: byte 102400: control-character: U+1 (decimal)"}));

TEST(TextFrontend, EspeakMnemonicsOfVariedTextAllMap) {
  // Exercises rarer mnemonics (r-coloured vowels, flaps, glottal stop, syllabic n and l).
  const Speech s = speak("Their fire near the car park certainly sounded better, didn't it? "
                         "Poor Joy saw the bottle; usually a measure of beige ink. Me all.");
  expect_contiguous(s);
  std::set<std::string> mnemonics;
  for (const auto& e : s.events) mnemonics.insert(e.espeak);
  EXPECT_TRUE(mnemonics.count("t#") + mnemonics.count("?") > 0);
  EXPECT_GT(mnemonics.size(), 30u);
}

// espeak-ng keeps state between calls (its pitch flutter advances), so audio is not
// bit-identical from call to call; the phone sequence is, and parallel calls must not interfere.
TEST(TextFrontend, ConcurrentCallsAreSerialised) {
  const std::string expected = arpabet_of(speak("hello world"));
  std::vector<Speech> results(3);
  std::vector<std::thread> threads;
  for (auto& r : results) threads.emplace_back([&r] { r = speak("hello world"); });
  for (auto& t : threads) t.join();
  for (const auto& r : results) {
    expect_contiguous(r);
    EXPECT_EQ(arpabet_of(r), expected);
  }
}

TEST(Speech, WavRoundTrip) {
  const Speech s = speak("a bob");
  const auto path = std::filesystem::temp_directory_path() / "fapcast_frontend_test.wav";
  write_wav(path, s.audio);
  const Audio back = read_wav(path);
  EXPECT_EQ(back.sample_rate.hz, s.audio.sample_rate.hz);
  EXPECT_EQ(back.samples, s.audio.samples);
  EXPECT_THROW(read_wav(path, 10), std::runtime_error);
  std::filesystem::remove(path);
  EXPECT_THROW(read_wav(path), std::runtime_error);
  EXPECT_THROW(write_wav("/nonexistent-dir/x.wav", s.audio), std::runtime_error);
}

}  // namespace
}  // namespace fapcast

namespace fapcast {
namespace {

// Nonsense items of the recording script are spoken from espeak-ng phoneme input: the phones
// that come back are the ones written.
TEST(TextFrontend, PhonemeInputSpeaksTheWrittenPhones) {
  SpeakOptions options;
  options.phoneme_input = true;
  const Speech s = speak("[[b'A:d]]", options);
  expect_contiguous(s);
  std::string non_silent;
  for (const auto& p : s.phones) {
    if (p.phone != Phone::SIL) non_silent += std::string(arpabet(p.phone)) + " ";
  }
  EXPECT_EQ(non_silent, "B AA D ");
}

}  // namespace
}  // namespace fapcast

namespace fapcast {
namespace {

TEST(TextFrontendRate, RateFactorChangesTheSpeakingRateAndNotThePhones) {
  SpeakOptions slow, fast;
  slow.rate_factor = 0.8;
  fast.rate_factor = 1.3;
  const Speech a = speak("the quick brown fox jumps", slow);
  const Speech b = speak("the quick brown fox jumps", fast);
  EXPECT_LT(static_cast<double>(b.audio.samples.size()), 0.8 * static_cast<double>(a.audio.samples.size()));
  ASSERT_EQ(a.phones.size(), b.phones.size());
  for (std::size_t i = 0; i < a.phones.size(); ++i) EXPECT_EQ(a.phones[i].phone, b.phones[i].phone) << i;
  // The rate does not stick: a default call afterwards speaks at the default rate again.
  const Speech c = speak("the quick brown fox jumps");
  EXPECT_GT(static_cast<double>(c.audio.samples.size()), 1.1 * static_cast<double>(b.audio.samples.size()));
}

}  // namespace
}  // namespace fapcast
