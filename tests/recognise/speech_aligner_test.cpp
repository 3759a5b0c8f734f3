#include "fapcast/recognise/speech_aligner.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "fapcast/core/file_io.hpp"
#include "fapcast/core/wav_file.hpp"

namespace fapcast {
namespace {

const std::string kEmuAe = std::string(FAPCAST_TEST_DATA) + "/speech/emu-ae/";

// A word the dictionary lacks ("beautifull" is no CMUdict entry) is aligned with espeak-ng's
// pronunciation of it, and keeps its spelling in the output.
TEST(SpeechAligner, AWordOutsideTheDictionaryGetsEspeakNgsPronunciation) {
  SpeechAligner aligner;
  const Audio audio = read_wav(kEmuAe + "msajc003.wav");
  const SpeechAlignment a =
      aligner.align(audio, parse_transcript("amongst her friends she was considered beautifull", "t.txt"), "msajc003.wav");
  ASSERT_EQ(a.words.size(), 7u);
  EXPECT_EQ(a.words[6].text, "beautifull");
  EXPECT_EQ(a.words[6].byte_offset, 39u);
  EXPECT_FALSE(a.words[6].low_confidence) << a.words[6].score_per_frame;
  // its phones are B Y UW T ... as for "beautiful": the first is B, the word ends with the speech
  std::size_t phones = 0;
  Phone first = Phone::SIL;
  for (const SpeechSegment& s : a.segments)
    if (s.word == 6 && s.kind == SpeechSegmentKind::phone) {
      if (phones++ == 0) first = s.phone;
    }
  EXPECT_EQ(first, Phone::B);
  EXPECT_GE(phones, 6u);
  EXPECT_GT(a.words[6].end_sample, a.samples * 8 / 10);
}

TEST(SpeechAligner, SegmentsCoverTheRecordingOnItsOwnTimeline) {
  SpeechAligner aligner;
  const Audio audio = read_wav(kEmuAe + "msajc010.wav");
  const SpeechAlignment a =
      aligner.align(audio, parse_transcript(read_file(kEmuAe + "msajc010.txt"), "msajc010.txt"), "msajc010.wav");
  EXPECT_EQ(a.sample_rate, audio.sample_rate);  // 20 kHz, not the decoder's 16
  EXPECT_EQ(a.samples, audio.instants());
  ASSERT_FALSE(a.segments.empty());
  EXPECT_EQ(a.segments.front().start_sample, 0);
  EXPECT_EQ(a.segments.back().end_sample, a.samples);
  for (std::size_t i = 1; i < a.segments.size(); ++i) EXPECT_EQ(a.segments[i].start_sample, a.segments[i - 1].end_sample);
  EXPECT_EQ(a.segments.front().kind, SpeechSegmentKind::silence);
}

// The phones of word `word` in `a`.
std::vector<Phone> word_phones(const SpeechAlignment& a, int word) {
  std::vector<Phone> out;
  for (const SpeechSegment& s : a.segments)
    if (s.word == word && s.kind == SpeechSegmentKind::phone) out.push_back(s.phone);
  return out;
}

// msajc003's talker is Australian, non-rhotic: the hand labels have "k H @ n s I d @ d" for
// "considered". The US dictionary has only K AH N S IH D ER D (its AH a schwa, AX, as espeak-ng
// reads it); read in en-gb, espeak-ng adds
// k@ns'Id3d (its 3 a schwa here), and the aligner takes it.
TEST(SpeechAligner, ReadInEnGbAWordGetsEspeakNgsNonRhoticVariantWhereItFitsBetter) {
  const Audio audio = read_wav(kEmuAe + "msajc003.wav");
  const Transcript t = parse_transcript(read_file(kEmuAe + "msajc003.txt"), "msajc003.txt");
  ASSERT_EQ(t.words[5].key, "considered");
  const std::vector<Phone> us = word_phones(SpeechAligner().align(audio, t, "msajc003.wav"), 5);
  const std::vector<Phone> gb = word_phones(SpeechAligner({.language = "en-gb"}).align(audio, t, "msajc003.wav"), 5);
  using enum Phone;
  EXPECT_EQ(us, (std::vector<Phone>{K, AX, N, S, IH, D, ER, D}));  // espeak-ng reads k@ns'Id3d
  EXPECT_EQ(gb, (std::vector<Phone>{K, AX, N, S, IH, D, AX, D}));  // both schwas, as the hand labels
}

// Weak forms where the talker uses them, strong forms where not (msajc003 and msajc015, hand
// labels in EMU SAMPA): "amongst her friends" has no h, "@:" alone, and the aligner takes the weak
// form AX over CMUdict's HH ER; "he emphasized" has "h i:", and HH IY stays over the weak IY.
TEST(SpeechAligner, AFunctionWordGetsItsWeakFormWhereTheTalkerSaysIt) {
  using enum Phone;
  const Audio a003 = read_wav(kEmuAe + "msajc003.wav");
  const Transcript t003 = parse_transcript(read_file(kEmuAe + "msajc003.txt"), "msajc003.txt");
  ASSERT_EQ(t003.words[1].key, "her");
  EXPECT_EQ(word_phones(SpeechAligner().align(a003, t003, "msajc003.wav"), 1), (std::vector<Phone>{AX}));
  EXPECT_EQ(word_phones(SpeechAligner({.weak_forms = false}).align(a003, t003, "msajc003.wav"), 1),
            (std::vector<Phone>{HH, ER}));

  const Audio a015 = read_wav(kEmuAe + "msajc015.wav");
  const Transcript t015 = parse_transcript(read_file(kEmuAe + "msajc015.txt"), "msajc015.txt");
  ASSERT_EQ(t015.words[0].key, "he");
  EXPECT_EQ(word_phones(SpeechAligner().align(a015, t015, "msajc015.wav"), 0), (std::vector<Phone>{HH, IY}));
}

TEST(SpeechAligner, AnUnknownLanguageIsABugNamingEspeakNgsVoices) {
  try {
    SpeechAligner({.language = "en-xx"});
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "SpeechAligner: unknown language 'en-xx' (`espeak-ng --voices` lists the installed ones)");
  }
}

TEST(SpeechAligner, AFrameRateOtherThan100Or200IsABug) {
  EXPECT_THROW(SpeechAligner({.frames_per_second = 150}), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
