// The reference talker: what it writes reads back through the importers, takes are reproducible,
// and everything it writes says SYNTHETIC (pose removal on its takes:
// tests/pipeline/reference_talker_pose_test.cpp).
#include "fapcast/talker/reference_talker.hpp"

#include "fapcast/corpus/c3d.hpp"
#include "fapcast/face/marker_map.hpp"
#include "fapcast/core/synthetic_label.hpp"
#include "fapcast/corpus/textgrid.hpp"

#include "support/reference_takes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>

namespace fapcast {
namespace {

using test::rms_difference;
using test::script_word;
using test::test_actor;

TEST(ReferenceTalker, C3dAndTextGridReadBackWhatWasRecorded) {
  PortableRandom random(11);
  const ReferenceTake take = record_take(script_word("a pup"), "utt0001", test_actor(), random);
  ASSERT_GT(take.captured.frame_count(), 20);

  const C3dFile c3d = read_c3d(write_c3d(to_millimetres(take.captured), {c3d_synthetic_parameter()}), "utt0001.c3d");
  EXPECT_EQ(c3d.text_parameters.at("FAPCAST:SYNTHETIC"), kSyntheticLabel);
  const MarkerFrames<Centimetres> back = to_centimetres(c3d.markers);
  ASSERT_EQ(back.labels, take.captured.labels);
  ASSERT_EQ(back.frame_count(), take.captured.frame_count());
  std::size_t samples = 0;
  EXPECT_LT(rms_difference(back, take.captured, &samples), 1e-5) << "float32 mm in the file";
  for (Eigen::Index k = 0; k < back.frame_count(); ++k)
    for (Eigen::Index m = 0; m < back.marker_count(); ++m)
      ASSERT_EQ(back.present(m, k), take.captured.present(m, k)) << "marker " << m << " frame " << k;

  const Alignment alignment = read_textgrid(write_textgrid(take.alignment), "utt0001.TextGrid");
  EXPECT_EQ(alignment, take.alignment);
  EXPECT_TRUE(is_synthetic(alignment));
  const LabelTier* phones = alignment.find("phones");
  ASSERT_NE(phones, nullptr);
  std::string spelled;
  for (const auto& i : phones->intervals)
    if (i.label != "sil" && !i.label.empty()) spelled += i.label + " ";
  EXPECT_NE(spelled.find("P AH P"), std::string::npos) << spelled;
}

// Reproducibility across runs is a property of whole processes (espeak-ng keeps state between
// calls): tests/cli/corpus_cli_test.cpp records the same corpus twice and compares the bytes.
TEST(ReferenceTalker, AnotherSeedGivesAnotherTake) {
  PortableRandom a(5), c(6);
  const ReferenceTake ta = record_take(script_word("moon"), "x", test_actor(), a);
  const ReferenceTake tc = record_take(script_word("moon"), "x", test_actor(), c);
  EXPECT_GT(rms_difference(ta.captured, tc.captured), 1e-3);
}

TEST(ReferenceTalker, ActorIsNotTheGenericFace) {
  const double moved = (test_actor().neutral_cm - ict_face_model().neutral_cm).colwise().norm().maxCoeff();
  EXPECT_GT(moved, 0.1) << "cm: the identity mix must change the face";
}

TEST(ReferenceTalker, CorpusDirectoryHasManifestAndSaysSynthetic) {
  const auto dir = std::filesystem::temp_directory_path() / "fapcast-refcorpus-test";
  std::filesystem::remove_all(dir);
  RecordingScript script;
  script.items = {script_word("a bob"), script_word("strewn"), {ScriptSection::kNonsense, "B AA D", {}, "[[b'A:d]]", 1.0}};
  std::map<std::string, std::string> files;
  const auto summary = record_reference_corpus(script, dir, {.count = 0, .seed = 3, .script = {}},
                                               [&](const std::string& name, std::string_view bytes) {
                                                 files[name] = std::string(bytes);
                                               });
  EXPECT_EQ(summary.utterances, 3u);
  ASSERT_TRUE(files.count("manifest.json"));
  const auto manifest = nlohmann::json::parse(files["manifest.json"]);
  EXPECT_EQ(manifest["synthetic"], true);
  EXPECT_EQ(manifest["provenance"], kSyntheticLabel);
  ASSERT_EQ(manifest["utterances"].size(), 3u);
  for (const auto& u : manifest["utterances"]) {
    const std::string stem = u["id"];
    EXPECT_TRUE(files.count(stem + ".c3d")) << stem;
    EXPECT_TRUE(files.count(stem + ".TextGrid")) << stem;
    EXPECT_TRUE(std::filesystem::exists(dir / (stem + ".wav"))) << stem;
    EXPECT_EQ(read_wav(dir / (stem + ".wav")).sample_rate.hz, u["sample_rate_hz"]);
  }
  EXPECT_EQ(manifest["utterances"][2]["section"], "nonsense");
  std::filesystem::remove_all(dir);
}

// The nonsense items are there to record divisemes the words miss: espeak-ng must say each one
// as its phones. Read as plain mnemonics it did not for 18 of the default script's 80 (E@ r as
// the r-coloured 3, a I as the diphthong aI, a final I as the happy i, an r linking U@ to E).
TEST(ReferenceTalker, NonsenseItemsAreSaidAsSpelled) {
  std::size_t said = 0;
  for (const std::vector<Phone>& asked : nonsense_candidates()) {
    const std::string spelling = nonsense_espeak_phonemes(asked);
    // What espeak-ng adds by rule, and which loses no diviseme class pair that matters: a glide Y
    // between IY and a vowel.
    std::string expected;
    for (std::size_t k = 0; k < asked.size(); ++k) {
      expected += std::string(arpabet(asked[k])) + " ";
      if (asked[k] == Phone::IY && k + 1 < asked.size() && is_vowel(asked[k + 1])) expected += "Y ";
    }
    std::string heard;
    for (const TimedPhone& p : speak(spelling, {.phoneme_input = true}).phones)
      if (p.phone != Phone::SIL) heard += std::string(arpabet(p.phone)) + " ";
    EXPECT_EQ(heard, expected) << spelling;
    ++said;
  }
  // 20 letters, 10 of them consonants (R among them): 20^3 - 10^3 without a vowel, less the 10 x 10
  // of R, a consonant, a vowel.
  EXPECT_EQ(said, 8000u - 10u * 10u * 10u - 10u * 10u);
}

// What the corpus says it recorded is what espeak-ng said, not what the script asked for.
TEST(ReferenceTalker, CorpusCountsTheDivisemesSaidAndNamesThoseNotSaid) {
  const auto dir = std::filesystem::temp_directory_path() / "fapcast-refcorpus-said-test";
  std::filesystem::remove_all(dir);
  RecordingScript script;
  const std::vector<Phone> b_aa_d = {Phone::B, Phone::AA, Phone::D};
  const std::vector<Phone> uh_ax_eh = {Phone::UH, Phone::AX, Phone::EH};
  script.items = {{ScriptSection::kNonsense, "B AA1 D", {{b_aa_d, Stress::kPrimary}}, "[[b'A:d]]", 1.0},
                  // espeak-ng reads these mnemonics as the diphthong U@ and a linking r: U@rE
                  {ScriptSection::kNonsense, "UH1 AX1 EH1", {{uh_ax_eh, Stress::kPrimary}}, "[['U@E]]", 1.0}};
  const auto summary = record_reference_corpus(script, dir, {.count = 0, .seed = 3, .script = {}},
                                               [](const std::string&, std::string_view) {});
  std::string not_said;
  for (std::uint32_t d : summary.divisemes_not_said) not_said += diviseme_name(d) + " ";
  EXPECT_EQ(not_said, "near_close_rounded>schwa schwa>mid_front ");
  EXPECT_EQ(summary.divisemes_recorded, 8u);  // sil>b b>aa aa>d d>sil, sil>uh uh>r r>eh eh>sil
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fapcast
