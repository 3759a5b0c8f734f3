// `fapcast align` end to end on real recordings: the TextGrid it writes reads back with its phones
// and words; a recording that does not say its transcript exits 1 naming the word and the time;
// usage mistakes exit 2 (spec/recognise.md, spec/cli.md).
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/corpus/alignment_file.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace fapcast::test {
namespace {

namespace fs = std::filesystem;
const std::string kSpeech = std::string(FAPCAST_TEST_DATA) + "/speech/";

TEST(AlignCli, WritesATextGridOfPhonesAndWords) {
  const std::string dir = make_temp_dir("align-cli");
  const std::string wav = kSpeech + "arctic/arctic_a0009.wav", grid = dir + "/a0009.TextGrid";
  const auto r = run_command(fapcast("align " + wav + " --transcript " + kSpeech + "arctic/arctic_a0009.txt -o " + grid));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("a0009.TextGrid: 9 words, "), std::string::npos) << r.out;
  AlignmentFileOptions options;
  options.sample_rate = read_wav(wav).sample_rate;
  const AlignmentFile found = read_alignment_file(read_file(grid), grid, options);
  EXPECT_EQ(found.tier, "phones");
  ASSERT_FALSE(found.segments.empty());
  EXPECT_EQ(found.segments.front().kind, LabelKind::silence);  // the pause before "He"
  std::string said;
  for (const Interval& i : found.alignment.find("words")->intervals)
    if (!i.label.empty()) said += (said.empty() ? "" : " ") + i.label;
  EXPECT_EQ(said, "He turned sharply and faced Gregson across the table");
  fs::remove_all(dir);
}

// Praat's example recording says only "the north wind and the sun": the rest of the fable's first
// sentence is not in it, and the error says where the recording stops following the text.
TEST(AlignCli, ATranscriptTheRecordingDoesNotSayIsRefused) {
  const std::string dir = make_temp_dir("align-cli");
  const auto r = run_command(fapcast("align " + kSpeech + "nws/the_north_wind_and_the_sun.wav --text \"The north wind "
                                     "and the sun were disputing which was the stronger\" -o " + dir + "/nws.TextGrid"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("the_north_wind_and_the_sun.wav: transcript-mismatch: 1.28 s: the recording diverges from the "
                       "transcript at word 7 'were' (byte 27): not found in the recording"),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/nws.TextGrid"));
  fs::remove_all(dir);
}

// Without a transcript the words are recognised: MOCHA fsew0_001 says "This was easy for us.";
// the words heard and their confidence are noted on standard error, the TextGrid has both tiers.
TEST(AlignCli, WithoutATranscriptTheWordsAreRecognised) {
  const std::string dir = make_temp_dir("align-cli");
  const std::string wav = std::string(FAPCAST_TEST_DATA) + "/mocha/fsew0_001.wav", grid = dir + "/fsew0_001.TextGrid";
  const auto r = run_command(fapcast("align " + wav + " -o " + grid));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("fsew0_001.wav: no transcript: recognised "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" per frame, "), std::string::npos) << r.err;
  AlignmentFileOptions options;
  options.sample_rate = read_wav(wav).sample_rate;
  const AlignmentFile found = read_alignment_file(read_file(grid), grid, options);
  EXPECT_EQ(found.tier, "phones");
  std::string said;
  for (const Interval& i : found.alignment.find("words")->intervals)
    if (!i.label.empty()) said += (said.empty() ? "" : " ") + i.label;
  EXPECT_NE(said.find("was easy"), std::string::npos) << said;
  EXPECT_NE(r.err.find(said), std::string::npos) << r.err;
  fs::remove_all(dir);
}

// `eval align` on one reference recording: the table on standard output, the same figures as JSON.
TEST(AlignCli, EvalAlignScoresOneRecordingWithAndWithoutItsTranscript) {
  const std::string dir = make_temp_dir("align-cli");
  const auto r = run_command(fapcast("eval align " + std::string(FAPCAST_TEST_DATA) + " --recording fsew0_001 -q --json-out " +
                                     dir + "/align.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("within 10 / 20 / 25 / 50 ms"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("MOCHA-TIMIT"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("EMU ae"), std::string::npos) << r.out;
  const auto json = nlohmann::json::parse(read_file(dir + "/align.json"));
  EXPECT_NE(json.at("command").get<std::string>().find("--recording fsew0_001"), std::string::npos);
  ASSERT_EQ(json.at("sets").size(), 1u);  // one set: no "all" row
  const auto& set = json.at("sets")[0];
  EXPECT_EQ(set.at("set"), "MOCHA-TIMIT");
  EXPECT_EQ(set.at("recordings"), 1);
  EXPECT_GE(set.at("boundaries").get<int>(), 12);
  const double w10 = set.at("within_ms").at("10"), w25 = set.at("within_ms").at("25"), w50 = set.at("within_ms").at("50");
  EXPECT_LE(w10, w25);
  EXPECT_LE(w25, w50);
  EXPECT_GE(w25, 0.70);
  // Every reference phone is matched, substituted or deleted; the table prints "matched / of".
  const auto phones = set.at("reference_phones").get<std::size_t>();
  const auto matched = set.at("phones_matched").get<std::size_t>();
  EXPECT_EQ(matched + set.at("phones_substituted").get<std::size_t>() + set.at("phones_deleted").get<std::size_t>(),
            phones);
  EXPECT_GE(matched, phones / 2) << "the alignment names most of the reference's phones alike";
  EXPECT_NE(r.out.find(std::to_string(matched) + " / " + std::to_string(phones)), std::string::npos) << r.out;
  EXPECT_GE(set.at("frames").get<int>(), 200);  // 2.2 s at 10 ms
  EXPECT_GE(set.at("frame_share").get<double>(), 0.70);
  EXPECT_EQ(run_command(fapcast("eval align " + std::string(FAPCAST_TEST_DATA) + " --recording nope")).exit_code, 2);
  fs::remove_all(dir);
}

TEST(AlignCli, MistakesExitTwo) {
  EXPECT_EQ(run_command(fapcast("align a.wav --text hi --transcript a.txt -o a.TextGrid")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("align a.wav --text hi -o a.lab")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("align a.wav --text hi")).exit_code, 2);  // no -o
}

// An accent espeak-ng does not have is a usage mistake that says where the accents come from,
// before any file is read (a.wav does not exist).
TEST(AlignCli, AnUnknownLangIsAUsageErrorNamingEspeakNgsVoices) {
  const std::vector<std::string> commands = {"align a.wav --text hi --lang en-xx -o a.TextGrid",
                                             "animate a.wav --text hi --lang en-xx -o a.fap",
                                             "eval align " + std::string(FAPCAST_TEST_DATA) + " --lang en-xx"};
  for (const std::string& command : commands) {
    const auto r = run_command(fapcast(command));
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("--lang 'en-xx': not an installed espeak-ng language (espeak-ng --voices lists them)"),
              std::string::npos)
        << command << ": " << r.err;
  }
}

}  // namespace
}  // namespace fapcast::test
