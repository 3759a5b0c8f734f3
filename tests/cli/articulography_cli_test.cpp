// `fapcast eval articulography` end to end on MOCHA-TIMIT fsew0_001 (real EMA, its WAV and its
// phone alignment, tests/data/mocha): the face animated on a small SYNTHETIC voice from the
// reference alignment and from fapcast's own forced alignment, compared with the coils; and the
// refusals of inputs that cannot be compared (exit 1, named) and of bad usage (exit 2).
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/corpus/ema.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>

namespace fapcast::test {
namespace {

namespace fs = std::filesystem;

const std::string kMocha = std::string(FAPCAST_TEST_DATA) + "/mocha/fsew0_001";

// The voice is built once per process from 40 SYNTHETIC script items (as SayCli's); CTest runs
// each test in its own process, so the end-to-end checks share one test.
class ArticulographyCli : public ::testing::Test {
 public:
  static void SetUpTestSuite() {
    dir_ = new std::string(make_temp_dir("articulography-cli"));
    for (const std::string& step : {"corpus record-reference -q --count 40 --seed 1 -o " + *dir_ + "/corpus",
                                    "voice build -q " + *dir_ + "/corpus -o " + voice()}) {
      const auto r = run_command(fapcast(step));
      ASSERT_EQ(r.exit_code, 0) << step << "\n" << r.err;
    }
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static std::string voice() { return *dir_ + "/v.fapv"; }
  static std::string out(const std::string& name) { return *dir_ + "/" + name; }
  static std::string* dir_;
};
std::string* ArticulographyCli::dir_ = nullptr;

constexpr const char* kMeasures[] = {"lip_aperture", "jaw_opening", "jaw_opening_chin", "lower_lip_protrusion",
                                     "tongue_tip_height"};

// Both animations of the sentence: the real side is the same in each (it does not depend on the
// phones), the registration is the spec's (ui -> bn 57.7 mm, turned 18.7 deg), every score is a
// range ratio, a correlation and a lag inside the searched window; the table, the JSON and the
// SVG say the same.
TEST_F(ArticulographyCli, TheFsewSentenceAgainstItsEmaFromBothAlignments) {
  const auto r = run_command(fapcast("eval articulography " + kMocha + ".ema " + kMocha + ".wav " + kMocha +
                                     ".lab --text \"This was easy for us.\" --voice " + voice() + " --by-phone --json-out " +
                                     out("a.json") + " --svg-out " + out("a.svg") + " -q"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("## animated from the reference alignment"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("## animated from the own alignment (forced, transcript, accent US dictionary)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("## own alignment against the reference alignment"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(voice()), std::string::npos) << "the voice is named: " << r.out;
  const auto j = nlohmann::json::parse(read_file(out("a.json")));
  EXPECT_EQ(j["voice"], voice());
  ASSERT_EQ(j["animations"].size(), 2u);
  EXPECT_EQ(j["animations"][0]["phones_from"], "reference alignment");
  for (const auto& a : j["animations"]) {
    EXPECT_EQ(a["ema"]["frames"], 966);
    EXPECT_NEAR(a["ema"]["end_s"].get<double>(), 1.93, 1e-9);
    EXPECT_NEAR(a["registration"]["nose_distance_mm"].get<double>(), 57.7, 0.1);
    EXPECT_NEAR(a["registration"]["rotation_deg"].get<double>(), 18.7, 0.3);
    EXPECT_EQ(a["registration"]["forward_sign"], -1);  // MOCHA's x points back
    // The real talker's ranges (p95 - p5): 11.1 mm lip aperture, 3.9 mm incisor distance.
    EXPECT_NEAR(a["measures"]["lip_aperture"]["range_real_mm"].get<double>(), 11.08, 0.2);
    EXPECT_NEAR(a["measures"]["jaw_opening"]["range_real_mm"].get<double>(), 3.88, 0.1);
    EXPECT_EQ(a["curves"]["rate_hz"], 100);
    for (const char* m : kMeasures) {
      EXPECT_EQ(a["curves"]["real_mm"][m].size(), 194u) << m;  // 0 to 1.93 s at 100 Hz
      EXPECT_EQ(a["curves"]["ours_mm"][m].size(), 194u) << m;
      const auto& s = a["measures"][m];
      EXPECT_EQ(s["range_real_mm"], j["animations"][0]["measures"][m]["range_real_mm"]) << m;
      EXPECT_GT(s["range_ours_mm"].get<double>(), 0) << m;
      EXPECT_NEAR(s["range_ratio"].get<double>(), s["range_ours_mm"].get<double>() / s["range_real_mm"].get<double>(), 1e-9);
      EXPECT_LE(std::abs(s["r_zero_lag"].get<double>()), 1) << m;
      EXPECT_GE(s["r_best_lag"].get<double>(), s["r_zero_lag"].get<double>()) << m;
      EXPECT_LE(std::abs(s["best_lag_ms"].get<double>()), 200) << m;
      EXPECT_EQ(s["best_lag_at_window_edge"], std::abs(s["best_lag_ms"].get<double>()) == 200) << m;
    }
  }
  // Where r is lost: one row per animated phone (17: fsew0_001.lab's 18 segments less the pause
  // after the breath, which the inhalation takes, AX from 0.25 to 0.35 s), spans that tile the
  // grid, shares >= 0 that add up to 1 - r.
  const auto& loss = j["animations"][0]["loss_by_phone"];
  ASSERT_EQ(loss.size(), 17u);
  EXPECT_EQ(loss[0]["phone"], "SIL");
  EXPECT_EQ(loss[0]["start_s"], 0.0);
  EXPECT_EQ(loss[1]["phone"], "AX");
  EXPECT_NEAR(loss[1]["start_s"].get<double>(), 0.25, 1e-9);
  EXPECT_NEAR(loss[1]["end_s"].get<double>(), 0.35, 1e-9);
  EXPECT_EQ(loss[2]["phone"], "DH");
  EXPECT_NEAR(loss[16]["end_s"].get<double>(), 1.94, 1e-9);  // the grid's 194 samples
  for (std::size_t i = 1; i < loss.size(); ++i) EXPECT_EQ(loss[i]["start_s"], loss[i - 1]["end_s"]) << i;
  for (const auto& a : j["animations"]) {  // the own alignment's phones too
    ASSERT_FALSE(a["loss_by_phone"].empty());
    for (const char* m : kMeasures) {
      double sum = 0;
      for (const auto& p : a["loss_by_phone"]) {
        EXPECT_GE(p["loss"][m].get<double>(), 0) << m;
        sum += p["loss"][m].get<double>();
      }
      EXPECT_NEAR(sum, 1 - a["measures"][m]["r_zero_lag"].get<double>(), 1e-9) << m;
    }
  }
  EXPECT_NE(r.out.find("where r is lost, phone by phone"), std::string::npos) << r.out;
  std::ostringstream whole;
  whole.setf(std::ios::fixed);
  whole.precision(3);
  whole << "| whole take (1 - r) | 0.00 | 1.94 | "
        << 1 - j["animations"][0]["measures"]["lip_aperture"]["r_zero_lag"].get<double>() << " |";
  EXPECT_NE(r.out.find(whole.str()), std::string::npos) << whole.str() << "\n" << r.out;

  // The calibration against real articulography (spec/talker.md): the jaw and the lower lip's
  // protrusion move about as far as the real talker's. The uncalibrated talker's were 3.7 and
  // 2.5 times the real ranges on the default voice.
  for (const char* m : {"jaw_opening", "lower_lip_protrusion"}) {
    const double ratio = j["animations"][0]["measures"][m]["range_ratio"].get<double>();
    EXPECT_GT(ratio, 0.5) << m;
    EXPECT_LT(ratio, 2.0) << m;
  }
  // The table's first row is the JSON's lip aperture.
  std::ostringstream row;
  const auto& lip = j["animations"][0]["measures"]["lip_aperture"];
  row.setf(std::ios::fixed);
  row.precision(2);
  row << "| lip aperture | " << lip["range_real_mm"].get<double>() << " | " << lip["range_ours_mm"].get<double>() << " | "
      << lip["range_ratio"].get<double>() << " |";
  EXPECT_NE(r.out.find(row.str()), std::string::npos) << row.str() << "\n" << r.out;
  // --tilt turns the coils further: the rotation-free incisor distance keeps its range, the
  // lip aperture (measured along "up") does not.
  const auto t = run_command(fapcast("eval articulography " + kMocha + ".ema " + kMocha + ".wav " + kMocha +
                                     ".lab --tilt 10 --voice " + voice() + " --json-out " + out("t.json") + " -q"));
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find(" --tilt 10\n"), std::string::npos) << t.out;
  const auto tilted = nlohmann::json::parse(read_file(out("t.json")))["animations"][0];
  const auto& upright = j["animations"][0];
  EXPECT_NEAR(tilted["registration"]["rotation_deg"].get<double>(),
              upright["registration"]["rotation_deg"].get<double>() + 10, 1e-9);
  EXPECT_NEAR(tilted["measures"]["jaw_opening"]["range_real_mm"].get<double>(),
              upright["measures"]["jaw_opening"]["range_real_mm"].get<double>(), 1e-9);
  EXPECT_GT(std::abs(tilted["measures"]["lip_aperture"]["range_real_mm"].get<double>() -
                     upright["measures"]["lip_aperture"]["range_real_mm"].get<double>()),
            0.2);
  EXPECT_EQ(tilted["measures"]["lip_aperture"]["range_ours_mm"], upright["measures"]["lip_aperture"]["range_ours_mm"]);

  // --talker adds the SYNTHETIC reference talker's own articulation of the same phones, after the
  // voice's animations (whose order and effect table stay): the same real side, a face that is not
  // the voice's, and, as calibrated (spec/talker.md), lips that open about as far as the real
  // talker's and move with them. The same run weighs the search's jaw term (spec/search.md): the
  // voice's units change, the talker's articulation does not depend on them.
  const auto k = run_command(fapcast("eval articulography " + kMocha + ".ema " + kMocha + ".wav " + kMocha +
                                     ".lab --talker --jaw-weight 3 --voice " + voice() + " --json-out " + out("k.json") + " -q"));
  ASSERT_EQ(k.exit_code, 0) << k.err;
  EXPECT_NE(k.out.find(" --jaw-weight 3 --talker\n"), std::string::npos) << k.out;
  EXPECT_NE(k.out.find("## the reference talker (SYNTHETIC), reference alignment, no voice"), std::string::npos) << k.out;
  const auto kj = nlohmann::json::parse(read_file(out("k.json")));
  ASSERT_EQ(kj["animations"].size(), 2u);
  EXPECT_EQ(kj["animations"][0]["animated_by"], "voice");
  EXPECT_NE(kj["animations"][0]["curves"]["ours_mm"]["jaw_opening"], j["animations"][0]["curves"]["ours_mm"]["jaw_opening"])
      << "the jaw term chose other units";
  // --jaw-level moves the voice's slow jaw towards the wanted one (spec/synthesis.md, "The jaw's
  // level"): the same units, another jaw; the talker's articulation does not take it.
  const auto l = run_command(fapcast("eval articulography " + kMocha + ".ema " + kMocha + ".wav " + kMocha +
                                     ".lab --talker --jaw-level 1 --voice " + voice() + " --json-out " + out("l.json") + " -q"));
  ASSERT_EQ(l.exit_code, 0) << l.err;
  EXPECT_NE(l.out.find(" --jaw-level 1 --talker\n"), std::string::npos) << l.out;
  const auto lj = nlohmann::json::parse(read_file(out("l.json")));
  EXPECT_EQ(lj["animations"][0]["synthesis"]["units"], j["animations"][0]["synthesis"]["units"]);
  double jaw_change = 0;
  const auto& levelled_jaw = lj["animations"][0]["curves"]["ours_mm"]["jaw_opening"];
  const auto& recorded_jaw = j["animations"][0]["curves"]["ours_mm"]["jaw_opening"];
  for (std::size_t n = 0; n < levelled_jaw.size(); ++n)
    jaw_change = std::max(jaw_change, std::abs(levelled_jaw[n].get<double>() - recorded_jaw[n].get<double>()));
  EXPECT_GT(jaw_change, 0.2) << "the jaw moved (mm)";
  EXPECT_EQ(lj["animations"][1]["curves"]["ours_mm"], kj["animations"][1]["curves"]["ours_mm"]) << "the talker is not levelled";
  const auto& talker = kj["animations"][1];
  EXPECT_EQ(talker["animated_by"], "reference talker (SYNTHETIC)");
  EXPECT_EQ(talker["synthesis"]["units"], 0);
  EXPECT_FALSE(talker["synthesis"].contains("unit_sources")) << "the talker has no units";
  // Where the voice's units come from (select/unit_sources.hpp): one entry per unit, together
  // covering the phones in order, each naming its take and bracketing as many recorded phones as
  // it stands for; the report lists them under the table.
  const auto& voice_synthesis = kj["animations"][0]["synthesis"];
  ASSERT_EQ(voice_synthesis["unit_sources"].size(), voice_synthesis["units"].get<std::size_t>());
  std::size_t next_phone = 0;
  for (const auto& u : voice_synthesis["unit_sources"]) {
    EXPECT_EQ(u["first_phone"].get<std::size_t>(), next_phone);
    const std::string asked = u["phones"], take = u["take_phones"];
    const std::size_t count = static_cast<std::size_t>(std::count(asked.begin(), asked.end(), ' ')) + 1;
    next_phone += count;
    const auto open = take.find('['), close = take.find(']');
    ASSERT_TRUE(open != std::string::npos && close != std::string::npos && open < close) << take;
    const std::string recorded = take.substr(open + 1, close - open - 1);
    EXPECT_EQ(static_cast<std::size_t>(std::count(recorded.begin(), recorded.end(), ' ')) + 1, count)
        << asked << " <- " << take;
    EXPECT_NE(k.out.find(asked + " <- " + std::to_string(u["take"].get<int>()) + ": " + take), std::string::npos) << k.out;
  }
  EXPECT_EQ(next_phone, voice_synthesis["phones"].get<std::size_t>());
  EXPECT_EQ(talker["curves"]["real_mm"]["lip_aperture"], kj["animations"][0]["curves"]["real_mm"]["lip_aperture"]);
  EXPECT_NE(talker["curves"]["ours_mm"]["lip_aperture"], kj["animations"][0]["curves"]["ours_mm"]["lip_aperture"]);
  EXPECT_EQ(talker["curves"]["ours_mm"]["tongue_tip_height"], kj["animations"][0]["curves"]["ours_mm"]["tongue_tip_height"])
      << "the same parametric tongue";
  const auto& talker_lips = talker["measures"]["lip_aperture"];
  EXPECT_GT(talker_lips["range_ratio"].get<double>(), 0.8);
  EXPECT_LT(talker_lips["range_ratio"].get<double>(), 1.25);
  EXPECT_GT(talker_lips["r_zero_lag"].get<double>(), 0.4);

  const std::string svg = read_file(out("a.svg"));
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  for (const char* label : {"lip aperture (mm", "jaw opening (mm", "jaw opening (chin 2.1) (mm", "lower-lip protrusion",
                            "tongue-tip height", "real (EMA)", "own alignment (forced, transcript, accent US dictionary)"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
}

// The own alignment read as southern British (MOCHA's fsew0): the command and the heading say so.
TEST_F(ArticulographyCli, TheOwnAlignmentSaysWhichAccentItWasReadIn) {
  const auto r = run_command(fapcast("eval articulography " + kMocha + ".ema " + kMocha + ".wav " + kMocha +
                                     ".lab --text \"This was easy for us.\" --lang en-gb --voice " + voice() + " -q"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(" --lang en-gb --voice "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("## animated from the own alignment (forced, transcript, accent en-gb)"), std::string::npos) << r.out;
}

// Refusals that come before any voice is opened (the voice named does not exist): exit 1 naming
// the file and the rule, or exit 2 for usage.
TEST(ArticulographyCliInput, InputsThatCannotBeComparedAreRefused) {
  const std::string dir = make_temp_dir("articulography-bad");
  const std::string no_voice = " --voice " + dir + "/missing.fapv";
  // The EMA stops at 0.6 s; the sentence is spoken until 1.67 s.
  std::istringstream rows(read_file(kMocha + ".ema"));
  std::string line, shortened;
  for (int i = 0; i < 300 && std::getline(rows, line); ++i) shortened += line + "\n";
  write_file_atomically(dir + "/short.ema", shortened);
  auto r = run_command(fapcast("eval articulography " + dir + "/short.ema " + kMocha + ".wav " + kMocha + ".lab" + no_voice));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(kMocha + ".lab: articulography-span: a phone spoken from"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("short.ema (0.000 to 0.598 s)"), std::string::npos) << r.err;

  // Without the nose-bridge coil there is no head pitch to register (an EST file names its coils).
  MarkerFrames<Millimetres> ema = read_ema(read_file(kMocha + ".ema"), kMocha + ".ema");
  const Eigen::Index bn = *ema.find("bn");
  ASSERT_EQ(bn, ema.marker_count() - 1);  // the last in MOCHA's order
  ema.labels.pop_back();
  ema.positions.conservativeResize(3 * bn, Eigen::NoChange);
  write_file_atomically(dir + "/no-bn.ema", write_ema_est(ema, EstEncoding::ascii));
  r = run_command(fapcast("eval articulography " + dir + "/no-bn.ema " + kMocha + ".wav " + kMocha + ".lab" + no_voice));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("no-bn.ema: ema-coils: no samples of coil 'bn'"), std::string::npos) << r.err;

  write_file_atomically(dir + "/text.ema", "this is not articulography\n");
  r = run_command(fapcast("eval articulography " + dir + "/text.ema " + kMocha + ".wav " + kMocha + ".lab" + no_voice));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("text.ema"), std::string::npos) << r.err;

  r = run_command(fapcast("eval articulography " + kMocha + ".ema " + kMocha + ".wav " + kMocha + ".lab" + no_voice +
                          " --json-out " + dir + "/no/such/dir/a.json"));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("a.json"), std::string::npos) << r.err;

  r = run_command(fapcast("eval articulography " + kMocha + ".ema " + kMocha + ".wav --tier phones"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  r = run_command(fapcast("eval articulography " + kMocha + ".ema " + kMocha + ".wav --text a --transcript " + kMocha +
                          ".txt"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  r = run_command(fapcast("eval articulography " + kMocha + ".ema"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  // an accent without a transcript to read in it
  r = run_command(fapcast("eval articulography " + kMocha + ".ema " + kMocha + ".wav " + kMocha + ".lab --lang en-gb"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--lang is the accent of the own alignment"), std::string::npos) << r.err;
  r = run_command(fapcast("eval articulography " + kMocha + ".ema " + kMocha + ".wav --text a --lang en-xx"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("espeak-ng --voices"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fapcast::test
