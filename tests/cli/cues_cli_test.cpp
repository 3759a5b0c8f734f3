// `say` and `animate --cues-out` end to end: one file per Rhubarb format, read back with a real
// parser (nlohmann-json, expat) and checked against Rhubarb's README: its fields, times with two
// decimals rising within the recording, shapes among those drawn, X where the speech pauses;
// usage mistakes exit 2 before any file is written (spec/mouth-cues.md, spec/cli.md).
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"
#include "support/xml_elements.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/cues/mouth_shape.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>
#include <string>

namespace fapcast::test {
namespace {

namespace fs = std::filesystem;
const std::string kEmu = std::string(FAPCAST_TEST_DATA) + "/speech/emu-ae/msajc003";

// Centiseconds of "12.34" (two decimals, as Rhubarb writes times); -1 when it is not so written.
long centiseconds(const std::string& s) {
  const auto point = s.find('.');
  if (point == std::string::npos || point == 0 || s.size() != point + 3) return -1;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (i != point && (s[i] < '0' || s[i] > '9')) return -1;
  return std::stol(s.substr(0, point)) * 100 + std::stol(s.substr(point + 1));
}

TEST(CuesCli, SayWritesRhubarbTsvEndingAtTheRecordingsEnd) {
  const std::string dir = make_temp_dir("cues-cli");
  const auto r = run_command(fapcast("say \"Hi there, how are you?\" --cues-out " + dir + "/hi.tsv --wav-out " + dir +
                                     "/hi.wav"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(" mouth cues in " + dir + "/hi.tsv"), std::string::npos) << r.out;
  const Audio audio = read_wav(dir + "/hi.wav");
  const long duration = static_cast<long>(static_cast<std::int64_t>(audio.samples.size()) * 100 / audio.sample_rate.hz);
  std::istringstream lines(read_file(dir + "/hi.tsv"));
  std::string line;
  std::vector<std::pair<long, char>> rows;
  while (std::getline(lines, line)) {
    const auto tab = line.find('\t');
    ASSERT_NE(tab, std::string::npos) << line;
    ASSERT_EQ(line.size(), tab + 2) << line;
    rows.emplace_back(centiseconds(line.substr(0, tab)), line[tab + 1]);
    EXPECT_GE(rows.back().first, 0) << line;
    EXPECT_TRUE(mouth_shape_from_letter(rows.back().second)) << line;
  }
  ASSERT_GE(rows.size(), 4u);
  EXPECT_EQ(rows.front(), std::make_pair(0L, 'X'));  // the rest before the speech
  EXPECT_EQ(rows.back(), std::make_pair(duration, 'X'));  // the closing line: the end, mouth closed
  for (std::size_t i = 1; i + 1 < rows.size(); ++i) {
    EXPECT_LT(rows[i - 1].first, rows[i].first);
    EXPECT_NE(rows[i - 1].second, rows[i].second);
  }
  fs::remove_all(dir);
}

TEST(CuesCli, AnimateWritesRhubarbXmlWithXAtTheSilences) {
  const std::string dir = make_temp_dir("cues-cli");
  const auto r = run_command(fapcast("animate -q " + kEmu + ".wav " + kEmu + ".TextGrid --cues-out " + dir + "/c.xml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const XmlDocument doc = read_xml_elements(read_file(dir + "/c.xml"));
  ASSERT_EQ(doc.error, "");
  EXPECT_EQ(doc.encoding, "utf-8");
  ASSERT_GE(doc.elements.size(), 6u);
  EXPECT_EQ(doc.elements[0].path, "rhubarbResult");
  EXPECT_EQ(doc.elements[1].path, "rhubarbResult/metadata");
  EXPECT_EQ(doc.elements[2].path, "rhubarbResult/metadata/soundFile");
  EXPECT_EQ(doc.elements[2].text, fs::absolute(kEmu + ".wav").string());  // the full path, as Rhubarb's
  EXPECT_EQ(doc.elements[3].path, "rhubarbResult/metadata/duration");
  EXPECT_EQ(doc.elements[3].text, "2.90");  // 2.90445 s truncated
  EXPECT_EQ(doc.elements[4].path, "rhubarbResult/mouthCues");
  long previous_end = 0;
  char shape_at_10 = 0, shape_at_275 = 0;  // 0.10 s and 2.75 s: in the TextGrid's first and last pauses
  for (std::size_t i = 5; i < doc.elements.size(); ++i) {
    const XmlElement& cue = doc.elements[i];
    ASSERT_EQ(cue.path, "rhubarbResult/mouthCues/mouthCue");
    ASSERT_EQ(cue.attributes.size(), 2u);
    const long start = centiseconds(cue.attributes.at("start")), end = centiseconds(cue.attributes.at("end"));
    EXPECT_EQ(start, previous_end);
    EXPECT_LT(start, end);
    ASSERT_EQ(cue.text.size(), 1u);
    EXPECT_TRUE(mouth_shape_from_letter(cue.text[0])) << cue.text;
    if (start <= 10 && 10 < end) shape_at_10 = cue.text[0];
    if (start <= 275 && 275 < end) shape_at_275 = cue.text[0];
    previous_end = end;
  }
  EXPECT_EQ(previous_end, 290);
  EXPECT_EQ(shape_at_10, 'X');
  EXPECT_EQ(shape_at_275, 'X');
  fs::remove_all(dir);
}

TEST(CuesCli, FormatOptionAndBasicShapesOnlyWriteJson) {
  const std::string dir = make_temp_dir("cues-cli");
  const auto r = run_command(fapcast("say -q \"Five lovely valleys.\" --cues-out " + dir +
                                     "/cues.txt --cues-format json --extended-shapes \"\""));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir + "/cues.txt"));
  EXPECT_EQ(j.at("metadata").at("soundFile"), "");  // no --wav-out: no recording to name
  const double duration = j.at("metadata").at("duration").get<double>();
  EXPECT_GT(duration, 0.5);
  const auto& cues = j.at("mouthCues");
  ASSERT_GE(cues.size(), 3u);
  double previous_end = 0;
  for (const auto& cue : cues) {
    EXPECT_DOUBLE_EQ(cue.at("start").get<double>(), previous_end);
    previous_end = cue.at("end").get<double>();
    const std::string value = cue.at("value");
    ASSERT_EQ(value.size(), 1u);
    EXPECT_NE(std::string("ABCDEF").find(value), std::string::npos) << value;  // no G, H, X drawn
  }
  EXPECT_DOUBLE_EQ(previous_end, duration);
  EXPECT_EQ(cues.front().at("value"), "A");  // rest is the closed mouth without X
  fs::remove_all(dir);
}

TEST(CuesCli, MistakesExitTwoAndWriteNothing) {
  const std::string dir = make_temp_dir("cues-cli");
  const std::string out = dir + "/c.tsv";
  EXPECT_EQ(run_command(fapcast("say Hi --cues-out " + dir + "/c.txt")).exit_code, 2);  // no format
  EXPECT_EQ(run_command(fapcast("say Hi --cues-out " + out + " --extended-shapes GA")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("say Hi --cues-out " + out + " --rig arkit")).exit_code, 2);  // a rig needs -o
  EXPECT_EQ(run_command(fapcast("say Hi --cues-format tsv -o " + dir + "/x.fap")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("say Hi")).exit_code, 2);  // neither -o nor --cues-out
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir + "/x.fap"));
  // A folder that does not exist: exit 1, nothing written.
  EXPECT_EQ(run_command(fapcast("say Hi --cues-out " + dir + "/no/such/c.tsv")).exit_code, 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fapcast::test
