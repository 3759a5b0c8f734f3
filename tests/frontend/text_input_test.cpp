// Every installed espeak-ng language, voice variants, SSML and texts of any length through the
// front-end: no language aborts, phones come from IPA features, long texts are chunked by
// sentence and stay one contiguous timeline.
#include "fapcast/frontend/text_frontend.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

namespace fapcast {
namespace {

void expect_timeline(const Speech& s, std::string_view text) {
  ASSERT_FALSE(s.phones.empty());
  ASSERT_EQ(s.events.size(), s.phones.size());
  EXPECT_EQ(s.phones.front().start_sample, 0);
  EXPECT_EQ(s.phones.back().end_sample, static_cast<std::int64_t>(s.audio.samples.size()));
  for (std::size_t i = 1; i < s.phones.size(); ++i) {
    ASSERT_EQ(s.phones[i].start_sample, s.phones[i - 1].end_sample) << i;
    ASSERT_LT(s.phones[i].start_sample, s.phones[i].end_sample) << i;
  }
  for (const TimedWord& w : s.words) {
    ASSERT_LE(w.byte_offset + w.text.size(), text.size());
    EXPECT_EQ(text.substr(w.byte_offset, w.text.size()), w.text);
  }
}

std::size_t spoken_phones(const Speech& s) {
  std::size_t n = 0;
  for (const TimedPhone& p : s.phones) n += p.phone != Phone::SIL;
  return n;
}

std::string spoken_arpabet_of(const Speech& s) {
  std::string out;
  for (const TimedPhone& p : s.phones) {
    if (p.phone != Phone::SIL) out += std::string(arpabet(p.phone)) + " ";
  }
  return out;
}

TEST(Languages, EspeakListsManyLanguagesIncludingTheIssuesFour) {
  const std::vector<EspeakLanguage> languages = espeak_languages();
  EXPECT_GT(languages.size(), 100u);  // espeak-ng 1.51 lists 131 voices
  std::set<std::string> codes;
  for (const auto& l : languages) codes.insert(l.code);
  for (const char* code : {"ru", "ar", "hi", "ko", "fr", "de", "cmn", "en-us"}) EXPECT_TRUE(codes.contains(code)) << code;
}

// One process, one sample per language: digits (each language reads them in its own words)
// and a sentence in Latin script (languages of other scripts switch to English for it).
TEST(Languages, EveryInstalledLanguageSpeaksASampleWithoutError) {
  const std::string sample = "1 2 3 10 42. Hello, fapcast.";
  std::size_t languages = 0;
  for (const EspeakLanguage& language : espeak_languages()) {
    SpeakOptions options;
    options.language = language.code;
    options.rate_factor = 2.0;
    Speech s;
    try {
      s = speak(sample, options);
    } catch (const std::exception& e) {
      ADD_FAILURE() << language.code << ": " << e.what();
      continue;
    }
    expect_timeline(s, sample);
    EXPECT_GE(spoken_phones(s), 8u) << language.code;
    ++languages;
  }
  EXPECT_GT(languages, 100u);
}

struct NativeSample { std::string language; std::string text; std::vector<Phone> must_have; };
class NativeText : public testing::TestWithParam<NativeSample> {};
TEST_P(NativeText, SpeaksWithPhonesFromIpaFeatures) {
  SpeakOptions options;
  options.language = GetParam().language;
  const Speech s = speak(GetParam().text, options);
  expect_timeline(s, GetParam().text);
  const std::string phones = spoken_arpabet_of(s);
  for (const Phone p : GetParam().must_have) {
    EXPECT_NE(phones.find(std::string(arpabet(p)) + " "), std::string::npos) << arpabet(p) << " in " << phones;
  }
  ASSERT_FALSE(s.words.empty());
  EXPECT_EQ(s.words.front().text, GetParam().text.substr(0, s.words.front().text.size()));
}
// The four languages `say` aborted on, and two read with English rules before.
INSTANTIATE_TEST_SUITE_P(Issue18, NativeText, testing::Values(
    NativeSample{"ru", "Москва", {Phone::M, Phone::S, Phone::K, Phone::V}},
    NativeSample{"ar", "مرحبا بالعالم", {Phone::M, Phone::R, Phone::B, Phone::L}},
    NativeSample{"hi", "नमस्ते दुनिया", {Phone::N, Phone::M, Phone::S, Phone::D}},
    NativeSample{"ko", "안녕하세요", {Phone::N, Phone::S}},
    NativeSample{"fr", "bonjour le monde", {Phone::B, Phone::ZH, Phone::L, Phone::M}},
    NativeSample{"de", "Ich spreche Deutsch", {Phone::HH, Phone::SH, Phone::P, Phone::D}}));

// The issue's aborts were with the default voice: en-us switches to Russian, Arabic, Hindi or
// Korean by script, and those languages' mnemonics go through the IPA features.
TEST(Languages, DefaultVoiceReadsOtherScriptsWithoutAborting) {
  for (const std::string text : {"Москва", "مرحبا بالعالم", "नमस्ते दुनिया", "안녕하세요", "Γειά σου κόσμε"}) {
    Speech s;
    ASSERT_NO_THROW(s = speak(text)) << text;
    expect_timeline(s, text);
    EXPECT_GE(spoken_phones(s), 3u) << text;
  }
  const std::string moscow = spoken_arpabet_of(speak("Москва"));
  for (const char* p : {"M ", "S ", "K ", "V "}) EXPECT_NE(moscow.find(p), std::string::npos) << p << " in " << moscow;
}

TEST(Languages, VariantChangesTheVoiceNotThePhones) {
  const std::vector<std::string> variants = espeak_variants();
  ASSERT_FALSE(variants.empty());
  EXPECT_NE(std::find(variants.begin(), variants.end(), "f2"), variants.end());
  SpeakOptions plain, female;
  plain.language = female.language = "de";
  female.variant = "f2";
  const Speech a = speak("guten Tag", plain);
  const Speech b = speak("guten Tag", female);
  EXPECT_EQ(spoken_arpabet_of(a), spoken_arpabet_of(b));
  EXPECT_NE(a.audio.samples, b.audio.samples);
}

TEST(Languages, UnknownLanguageAndVariantAreClearErrors) {
  SpeakOptions bad_language;
  bad_language.language = "xx-nope";
  try {
    speak("hello", bad_language);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "espeak-ng: unknown language 'xx-nope' (`espeak-ng --voices` lists the installed ones)");
  }
  SpeakOptions bad_variant;
  bad_variant.variant = "zz";
  EXPECT_THROW(speak("hello", bad_variant), std::invalid_argument);
}

TEST(Languages, EnglishDefaultStillUsesTheMnemonicMapAfterOtherLanguages) {
  const Speech before = speak("a pup");
  SpeakOptions ru;
  ru.language = "ru";
  (void)speak("Москва", ru);
  const Speech after = speak("a pup");
  EXPECT_EQ(spoken_arpabet_of(before), spoken_arpabet_of(after));
  ASSERT_EQ(before.events.size(), after.events.size());
  for (std::size_t i = 0; i < before.events.size(); ++i) EXPECT_EQ(before.events[i].espeak, after.events[i].espeak) << i;
}

TEST(Ssml, TagsAreParsedNotSpoken) {
  const std::string text = "<speak>Hello <break time=\"300ms\"/> <emphasis>world</emphasis></speak>";
  SpeakOptions ssml;
  ssml.ssml = true;
  const Speech parsed = speak(text, ssml);
  const Speech spoken = speak(text);
  std::string words;
  for (const TimedWord& w : parsed.words) words += w.text + "|";
  EXPECT_EQ(words.find("speak"), std::string::npos) << words;
  EXPECT_EQ(words.find("emphasis"), std::string::npos) << words;
  EXPECT_EQ(parsed.words.size(), 2u) << words;
  EXPECT_GT(spoken.words.size(), parsed.words.size());  // as plain text the tags are read out
  // The break is a silence of at least its 300 ms between the two words.
  ASSERT_EQ(parsed.words.size(), 2u);
  const std::int64_t gap = parsed.words[1].start_sample - parsed.words[0].end_sample;
  EXPECT_GE(gap, parsed.audio.sample_rate.hz * 3 / 10);
}

TEST(Chunks, LongTextIsCutAtSentenceEndsWithinTheLimit) {
  std::string text;
  while (text.size() <= 40 * 1024) text += "The cat sat on the mat. Did it? Yes!\n";
  const std::vector<std::size_t> starts = chunk_offsets(text, kChunkBytes);
  ASSERT_GE(starts.size(), 10u);
  EXPECT_EQ(starts.front(), 0u);
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const std::size_t end = i + 1 < starts.size() ? starts[i + 1] : text.size();
    ASSERT_LT(starts[i], end);
    EXPECT_LE(end - starts[i], kChunkBytes);
    if (i > 0) {
      const char before = text[starts[i] - 2];
      EXPECT_TRUE(before == '.' || before == '?' || before == '!' || before == '\n') << i;
    }
  }
}

// Chinese, Hindi and Urdu write no space after a full stop: the chunks still end at one.
TEST(Chunks, ScriptsWithoutSpacesAreCutAfterTheirFullStops) {
  for (const std::string sentence : {"我们今天去公园散步。", "हम आज पार्क में टहलने गए।", "ہم آج پارک گئے۔"}) {
    std::string text;
    while (text.size() <= 3000) text += sentence;
    const auto starts = chunk_offsets(text, 1000);
    ASSERT_GE(starts.size(), 3u) << sentence;
    for (std::size_t i = 1; i < starts.size(); ++i) {
      EXPECT_EQ(text.compare(starts[i], sentence.size(), sentence), 0) << sentence << " chunk " << i;
      EXPECT_LE(starts[i] - starts[i - 1], 1000u);
    }
  }
}

TEST(Chunks, SentenceWithoutEndsIsCutAtSpacesThenAtCodePoints) {
  std::string words;
  while (words.size() < 3000) words += "word ";
  const auto by_space = chunk_offsets(words, 1000);
  for (std::size_t i = 1; i < by_space.size(); ++i) EXPECT_EQ(words[by_space[i] - 1], ' ');
  std::string cyrillic;
  while (cyrillic.size() < 3000) cyrillic += "ж";  // two bytes each, no spaces
  const auto by_code_point = chunk_offsets(cyrillic, 1001);
  ASSERT_GE(by_code_point.size(), 3u);
  for (std::size_t i = 1; i < by_code_point.size(); ++i) {
    EXPECT_EQ(by_code_point[i] % 2, 0u);  // never inside a code point
    EXPECT_LE(by_code_point[i] - by_code_point[i - 1], 1001u);
  }
  EXPECT_TRUE(chunk_offsets("", 100).empty());
}

// Over 32 KiB of input (the old cap), spoken in chunks as one contiguous timeline whose words
// point back into the text. The text is a formatted list: short items, long indentation, so
// that speaking it stays fast under the sanitizers.
TEST(Chunks, TextOver32KiBIsSpokenAsOneTimeline) {
  std::string text;
  int items = 0;
  while (text.size() <= 33 * 1024) {
    text += "Item " + std::to_string(++items) + "." + std::string(300, ' ') + "\n";
  }
  SpeakOptions fast;
  fast.rate_factor = 2.5;
  const Speech s = speak(text, fast);
  expect_timeline(s, text);
  std::size_t item_words = 0;
  std::size_t last_item = 0;
  for (const TimedWord& w : s.words) {
    if (w.text != "Item") continue;
    ++item_words;
    last_item = w.byte_offset;
  }
  EXPECT_EQ(item_words, static_cast<std::size_t>(items));
  EXPECT_EQ(last_item, text.rfind("Item"));
}

// Chunk by chunk: each chunk is a timeline of its own, bounded by kChunkBytes of text, and
// together they say what speak() says.
TEST(Chunks, SpeakChunksStreamsTheSameWordsInBoundedPieces) {
  std::string text;
  while (text.size() <= 9 * 1024) text += "Item " + std::to_string(text.size()) + "." + std::string(200, ' ') + "\n";
  SpeakOptions fast;
  fast.rate_factor = 2.5;
  std::size_t chunks = 0;
  std::vector<std::string> streamed;
  speak_chunks(text, fast, [&](Speech&& part) {
    ++chunks;
    ASSERT_FALSE(part.phones.empty());
    EXPECT_EQ(part.phones.front().start_sample, 0);
    EXPECT_EQ(part.phones.back().end_sample, static_cast<std::int64_t>(part.audio.samples.size()));
    for (const TimedWord& w : part.words) {
      EXPECT_EQ(text.substr(w.byte_offset, w.text.size()), w.text);
      streamed.push_back(w.text);
    }
  });
  EXPECT_GE(chunks, 3u);
  std::vector<std::string> whole;
  for (const TimedWord& w : speak(text, fast).words) whole.push_back(w.text);
  EXPECT_EQ(streamed, whole);
}

// What `say` keeps of a long text: the chunks' timing appended as they come (append_timing), each
// chunk's audio counted and let go. Every chunk's phones land shifted by the speech before it
// (a silence across the join made one), the whole is one timeline over all the samples, and no
// chunk carries more than its own stretch of the speech.
TEST(Chunks, TimingAppendedChunkByChunkIsOneTimeline) {
  std::string text;
  while (text.size() <= 9 * 1024) text += "Item " + std::to_string(text.size()) + ". Then a pause.\n";
  SpeakOptions fast;
  fast.rate_factor = 2.5;
  Speech timing;
  std::int64_t samples = 0;
  std::size_t largest = 0, chunks = 0;
  std::vector<std::string> streamed;
  speak_chunks(text, fast, [&](Speech&& part) {
    const Speech chunk = part;  // counted from its own start
    const std::size_t before = timing.phones.size();
    const std::size_t joined =
        before > 0 && timing.phones.back().phone == Phone::SIL && chunk.phones.front().phone == Phone::SIL ? 1 : 0;
    if (!append_timing(timing, std::move(part), samples)) return;
    ++chunks;
    ASSERT_EQ(timing.phones.size(), before + chunk.phones.size() - joined);
    for (std::size_t k = joined; k < chunk.phones.size(); ++k) {
      const TimedPhone& p = timing.phones[before + k - joined];
      EXPECT_EQ(p.phone, chunk.phones[k].phone);
      EXPECT_EQ(p.start_sample, chunk.phones[k].start_sample + samples);
      EXPECT_EQ(p.end_sample, chunk.phones[k].end_sample + samples);
    }
    for (const TimedWord& w : chunk.words) streamed.push_back(w.text);
    largest = std::max(largest, chunk.audio.samples.size());
    samples += static_cast<std::int64_t>(chunk.audio.samples.size());
  });
  EXPECT_GE(chunks, 3u);
  EXPECT_TRUE(timing.audio.samples.empty());
  EXPECT_GT(timing.audio.sample_rate.hz, 0);
  timing.audio.samples.resize(static_cast<std::size_t>(samples));
  expect_timeline(timing, text);
  std::vector<std::string> words;
  for (const TimedWord& w : timing.words) words.push_back(w.text);
  EXPECT_EQ(words, streamed);
  EXPECT_LT(largest, static_cast<std::size_t>(samples) / 2);  // each chunk <= kChunkBytes of > 9 KiB
  Speech none;
  EXPECT_FALSE(append_timing(none, Speech{}, 0));
  EXPECT_TRUE(none.phones.empty());
}

}  // namespace
}  // namespace fapcast
