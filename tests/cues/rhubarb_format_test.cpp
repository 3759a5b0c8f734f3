// The three result files checked field by field against Rhubarb Lip Sync's README ("Output
// formats"): JSON read back with nlohmann-json, XML with expat (support/xml_elements.hpp), TSV
// line by line; times with two
// decimals, rising, within the duration; shapes among the drawn ones; the TSV's closing line.
#include "fapcast/cues/rhubarb_format.hpp"
#include "support/xml_elements.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fapcast {
namespace {

// Rhubarb README's 'Hi' (its cue times), on a recording of 0.47 s.
RhubarbResult hi(MouthShapeSet drawn = MouthShapeSet::all()) {
  RhubarbResult r;
  r.cues = {{MouthShape::X, Centiseconds{0}, Centiseconds{5}},
            {MouthShape::D, Centiseconds{5}, Centiseconds{27}},
            {MouthShape::C, Centiseconds{27}, Centiseconds{31}},
            {MouthShape::B, Centiseconds{31}, Centiseconds{43}},
            {MouthShape::X, Centiseconds{43}, Centiseconds{47}}};
  r.duration = Centiseconds{47};
  r.sound_file = "C:\\Users\\Daniel\\hi & \"bye\" <1>.wav";
  r.drawn = drawn;
  return r;
}

// Seconds as Rhubarb writes them: digits, a point, two digits.
bool is_time(const std::string& s) {
  const auto point = s.find('.');
  if (point == std::string::npos || point == 0 || s.size() != point + 3) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return c == '.' || (c >= '0' && c <= '9'); }) &&
         std::count(s.begin(), s.end(), '.') == 1;
}

TEST(RhubarbFormat, FormatsByNameAndExtension) {
  EXPECT_EQ(rhubarb_format_from_name("tsv"), RhubarbFormat::kTsv);
  EXPECT_EQ(rhubarb_format_from_name("dat"), std::nullopt);
  EXPECT_EQ(rhubarb_format_from_path("out/hi.XML"), RhubarbFormat::kXml);
  EXPECT_EQ(rhubarb_format_from_path("hi.json"), RhubarbFormat::kJson);
  EXPECT_EQ(rhubarb_format_from_path("hi.txt"), std::nullopt);
  EXPECT_EQ(rhubarb_format_from_path("hi"), std::nullopt);
}

TEST(RhubarbFormat, TsvIsOneTimedShapePerLineThenTheEnd) {
  const std::string tsv = write_rhubarb(hi(), RhubarbFormat::kTsv);
  EXPECT_EQ(tsv, "0.00\tX\n0.05\tD\n0.27\tC\n0.31\tB\n0.43\tX\n0.47\tX\n");  // the README's example
  // Without X the closing line is A.
  const std::string basic = write_rhubarb(hi(*drawn_shapes("GH")), RhubarbFormat::kTsv);
  EXPECT_EQ(basic.substr(basic.rfind("0.47")), "0.47\tA\n");
  std::istringstream lines(tsv);
  std::string line;
  double last = -1;
  while (std::getline(lines, line)) {
    const auto tab = line.find('\t');
    ASSERT_NE(tab, std::string::npos) << line;
    EXPECT_TRUE(is_time(line.substr(0, tab))) << line;
    const double t = std::stod(line.substr(0, tab));
    EXPECT_GE(t, last);
    EXPECT_LE(t, 0.47);
    last = t;
    ASSERT_EQ(line.size(), tab + 2) << line;
    EXPECT_TRUE(mouth_shape_from_letter(line[tab + 1])) << line;
  }
}

TEST(RhubarbFormat, JsonHasTheMetadataAndTheCues) {
  const std::string text = write_rhubarb(hi(), RhubarbFormat::kJson);
  const nlohmann::json j = nlohmann::json::parse(text);
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j.size(), 2u);
  const auto& meta = j.at("metadata");
  EXPECT_EQ(meta.size(), 2u);
  EXPECT_EQ(meta.at("soundFile"), "C:\\Users\\Daniel\\hi & \"bye\" <1>.wav");
  EXPECT_DOUBLE_EQ(meta.at("duration").get<double>(), 0.47);
  const auto& cues = j.at("mouthCues");
  ASSERT_TRUE(cues.is_array());
  ASSERT_EQ(cues.size(), 5u);
  double previous_end = 0;
  const std::string letters = "XDCBX";
  for (std::size_t i = 0; i < cues.size(); ++i) {
    EXPECT_EQ(cues[i].size(), 3u);
    const double start = cues[i].at("start").get<double>(), end = cues[i].at("end").get<double>();
    EXPECT_DOUBLE_EQ(start, previous_end);  // contiguous from 0
    EXPECT_LT(start, end);
    EXPECT_LE(end, 0.47);
    EXPECT_EQ(cues[i].at("value"), std::string(1, letters[i]));
    previous_end = end;
  }
  EXPECT_DOUBLE_EQ(previous_end, 0.47);
  // Times keep two decimals as in the README ("start": 0.00), and its line layout.
  EXPECT_NE(text.find("    { \"start\": 0.00, \"end\": 0.05, \"value\": \"X\" },\n"), std::string::npos) << text;
  EXPECT_NE(text.find("    \"duration\": 0.47\n"), std::string::npos) << text;
}

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \n"), b = s.find_last_not_of(" \n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

TEST(RhubarbFormat, XmlHasTheMetadataAndTheCues) {
  const test::XmlDocument doc = test::read_xml_elements(write_rhubarb(hi(), RhubarbFormat::kXml));
  ASSERT_EQ(doc.error, "");
  EXPECT_EQ(doc.encoding, "utf-8");
  const auto& nodes = doc.elements;
  std::vector<std::string> paths;
  for (const test::XmlElement& n : nodes) paths.push_back(n.path);
  const std::vector<std::string> expected{"rhubarbResult", "rhubarbResult/metadata", "rhubarbResult/metadata/soundFile",
                                          "rhubarbResult/metadata/duration", "rhubarbResult/mouthCues",
                                          "rhubarbResult/mouthCues/mouthCue", "rhubarbResult/mouthCues/mouthCue",
                                          "rhubarbResult/mouthCues/mouthCue", "rhubarbResult/mouthCues/mouthCue",
                                          "rhubarbResult/mouthCues/mouthCue"};
  ASSERT_EQ(paths, expected);
  EXPECT_EQ(nodes[2].text, "C:\\Users\\Daniel\\hi & \"bye\" <1>.wav");  // escaped, read back
  EXPECT_EQ(nodes[3].text, "0.47");
  std::string previous_end = "0.00";
  const std::string letters = "XDCBX";
  for (std::size_t i = 5; i < nodes.size(); ++i) {
    const test::XmlElement& cue = nodes[i];
    ASSERT_EQ(cue.attributes.size(), 2u);
    const std::string start = cue.attributes.at("start"), end = cue.attributes.at("end");
    EXPECT_TRUE(is_time(start) && is_time(end)) << start << " " << end;
    EXPECT_EQ(start, previous_end);
    EXPECT_LT(std::stod(start), std::stod(end));
    EXPECT_EQ(trimmed(cue.text), std::string(1, letters[i - 5]));
    previous_end = end;
  }
  EXPECT_EQ(previous_end, "0.47");
}

TEST(RhubarbFormat, MouthCuesOfPhonesWriteValidFiles) {
  // A hand-made "Hi there" at 16 kHz, through the rules and all three writers.
  const SampleRate rate{16000};
  const std::vector<TimedPhone> phones{{Phone::SIL, 0, 1600},     {Phone::HH, 1600, 2800}, {Phone::AY, 2800, 6400},
                                       {Phone::DH, 6400, 7200},   {Phone::EH, 7200, 9000}, {Phone::R, 9000, 10400},
                                       {Phone::SIL, 10400, 16000}};
  RhubarbResult r;
  r.cues = mouth_cues(phones, rate, 16123);
  r.duration = truncated_centiseconds(16123, rate);
  r.sound_file = "/tmp/hi there.wav";
  const nlohmann::json j = nlohmann::json::parse(write_rhubarb(r, RhubarbFormat::kJson));
  ASSERT_FALSE(j.at("mouthCues").empty());
  EXPECT_EQ(j.at("mouthCues").front().at("value"), "X");  // the pause before HH
  EXPECT_EQ(j.at("mouthCues").back().at("value"), "X");   // and after "there"
  EXPECT_DOUBLE_EQ(j.at("mouthCues").back().at("end").get<double>(), 1.00);
  const test::XmlDocument doc = test::read_xml_elements(write_rhubarb(r, RhubarbFormat::kXml));
  EXPECT_EQ(doc.error, "");
  EXPECT_EQ(doc.elements.size(), 5 + r.cues.size());
  const std::string tsv = write_rhubarb(r, RhubarbFormat::kTsv);
  EXPECT_EQ(static_cast<std::size_t>(std::count(tsv.begin(), tsv.end(), '\n')), r.cues.size() + 1);
}

}  // namespace
}  // namespace fapcast
