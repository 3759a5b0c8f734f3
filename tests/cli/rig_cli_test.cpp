// `fapcast say --rig/--avatar/--vmc` end to end on a voice built from a small SYNTHETIC reference
// corpus, checked by the programs people use: three.js (GLTFLoader, AnimationMixer, CPU morphing and
// skinning) and headless Chromium on a Ready Player Me avatar, @pixiv/three-vrm and
// three-vrm-animation on a VRM, node-osc and liblo's oscdump on the live VMC stream; and the fit's
// accuracy targets (spec/rigs.md).
#include "cli/fapcast_command.hpp"
#include "support/bad_inputs.hpp"
#include "support/run_command.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <cstring>
#include <map>
#include <sstream>

namespace fapcast::test {
namespace {

namespace fs = std::filesystem;

const std::string kText = "Maybe the thin cat will go home. Bob bought a pup, and we sang.";
const std::string kViewer = std::string(FAPCAST_SOURCE_DIR) + "/tests/viewer";
const std::string kAvatar = std::string(FAPCAST_TEST_DATA) + "/avatars/brunette-t.glb";

std::string q(const std::string& s) { return "'" + s + "'"; }

class RigCli : public ::testing::Test {
 public:
  static void SetUpTestSuite() {
    dir_ = new std::string(make_temp_dir("rig-cli"));
    const auto r = run_command(fapcast("corpus record-reference -q --count 40 --seed 1 -o " + q(*dir_ + "/corpus")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto b = run_command(fapcast("voice build -q " + q(*dir_ + "/corpus") + " -o " + q(voice())));
    ASSERT_EQ(b.exit_code, 0) << b.err;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static std::string voice() { return *dir_ + "/v.fapv"; }
  static std::string out(const std::string& name) { return *dir_ + "/" + name; }
  static std::string say(const std::string& args) {
    return fapcast("say " + q(kText) + " --voice " + q(voice()) + " -q " + args);
  }
  static std::string* dir_;
};
std::string* RigCli::dir_ = nullptr;

double number_after(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  EXPECT_NE(at, std::string::npos) << label << " not in: " << text;
  return at == std::string::npos ? NAN : std::stod(text.substr(at + label.size()));
}

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    rows.emplace_back();
    std::stringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) rows.back().push_back(c);
  }
  return rows;
}

nlohmann::json node(const std::string& script, const std::string& args) {
  const auto r = run_command(q(FAPCAST_NODE) + " " + q(kViewer + "/" + script) + " " + args);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

// Visemes of the TalkingHead JSON as per-frame runs: [first frame, end frame) and name.
struct VisemeRun { int first, end; std::string viseme; };
std::vector<VisemeRun> viseme_runs(const nlohmann::json& th) {
  std::vector<VisemeRun> runs;
  for (std::size_t i = 0; i < th["visemes"].size(); ++i) {
    const int first = static_cast<int>(std::lround(th["vtimes"][i].get<double>() * 60 / 1000));
    const int end = static_cast<int>(std::lround((th["vtimes"][i].get<double>() + th["vdurations"][i].get<double>()) * 60 / 1000));
    runs.push_back({first, end, th["visemes"][i]});
  }
  return runs;
}
bool is_vowel(const std::string& v) { return v == "aa" || v == "E" || v == "I" || v == "O" || v == "U"; }

TEST_F(RigCli, ArkitLiveLinkCsvMeetsTheAccuracyTargets) {
  const auto r = run_command(say("-o " + q(out("say.csv"))));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // the fitted weights, applied back to the ICT face, reproduce the synthesised feature points
  EXPECT_LT(number_after(r.out, "ARKit fit: lips "), 0.5) << r.out;  // mm RMS, the aim
  EXPECT_LT(number_after(r.out, "), jaw "), 1.0) << r.out;          // mm RMS, the target
  const std::string csv = slurp(out("say.csv"));
  const std::string real = slurp(std::string(FAPCAST_TEST_DATA) + "/rig/live-link-face-S07-001-head.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), real.substr(0, real.find('\n')));
  const auto rows = csv_rows(csv);
  const int frames = static_cast<int>(number_after(r.out, ": "));  // "OUT: N frames at 60 fps"
  ASSERT_EQ(static_cast<int>(rows.size()), frames + 1);
  double jaw_max = 0;
  for (std::size_t f = 1; f < rows.size(); ++f) {
    ASSERT_EQ(rows[f].size(), 63u);
    EXPECT_EQ(rows[f][1], "61");
    for (std::size_t c = 2; c < 54; ++c) {
      const double v = std::stod(rows[f][c]);
      ASSERT_TRUE(v >= 0 && v <= 1) << "frame " << f << " column " << rows[0][c] << ": " << v;
    }
    jaw_max = std::max(jaw_max, std::stod(rows[f][2 + 17]));
  }
  EXPECT_GT(jaw_max, 0.2);  // the jaw opens
  EXPECT_TRUE(fs::exists(out("say.wav")));  // the sound beside it
}

// Also the mouth cues beside the rig (spec/mouth-cues.md): the same cues as --cues-out alone.
TEST_F(RigCli, OculusVisemesAgreeWithThePhones) {
  const auto r = run_command(say("--rig oculus -o " + q(out("oculus.json")) + " --cues-out " + q(out("both.json"))));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(" mouth cues in " + out("both.json")), std::string::npos) << r.out;
  const auto alone = run_command(fapcast("say " + q(kText) + " --cues-out " + q(out("alone.json"))));  // no voice
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  const nlohmann::json mouth = nlohmann::json::parse(slurp(out("both.json")));
  EXPECT_EQ(mouth.at("mouthCues"), nlohmann::json::parse(slurp(out("alone.json"))).at("mouthCues"));
  EXPECT_EQ(mouth.at("metadata").at("soundFile"), out("oculus.wav"));  // the WAV written beside the rig track
  EXPECT_GT(mouth.at("mouthCues").size(), 20u);  // a sentence of some 40 phones
  EXPECT_DOUBLE_EQ(mouth.at("mouthCues").back().at("end").get<double>(),
                   mouth.at("metadata").at("duration").get<double>());
  const auto th = nlohmann::json::parse(slurp(out("oculus.json")));
  const auto& vs = th["anim"]["vs"];
  const std::size_t frames = th["anim"]["dt"].size();
  int agree = 0;
  for (const VisemeRun& run : viseme_runs(th))
    for (int f = run.first; f < run.end && f < static_cast<int>(frames); ++f) {
      std::string best;
      double top = -1;
      for (const auto& [name, values] : vs.items())
        if (values[f].get<double>() > top) { top = values[f]; best = name; }
      static const std::map<std::string, std::string> th_to_morph{{"I", "viseme_I"}, {"O", "viseme_O"}, {"U", "viseme_U"}};
      const std::string want = th_to_morph.count(run.viseme) ? th_to_morph.at(run.viseme) : "viseme_" + run.viseme;
      agree += best == want;
    }
  const double agreement = static_cast<double>(agree) / static_cast<double>(frames);
  std::cout << "Oculus agreement with the phone timeline: " << 100 * agreement << " % of " << frames << " frames\n";
  EXPECT_GE(agreement, 0.95);
}

TEST_F(RigCli, AvatarSpeaksInThreeJsAndChromium) {
  const auto r = run_command(say("--avatar " + q(kAvatar) + " -o " + q(out("avatar.glb"))));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("52 morph targets driven"), std::string::npos) << r.out;
  ASSERT_EQ(run_command(say("--rig arkit -o " + q(out("timing.json")))).exit_code, 0);
  const auto runs = viseme_runs(nlohmann::json::parse(slurp(out("timing.json"))));
  // three.js's own morphing and skinning at every frame
  const int frames = static_cast<int>(number_after(r.out, ": "));
  std::string times;
  for (int f = 0; f < frames; ++f) times += (f ? "," : "") + std::to_string(f / 60.0);
  const auto j = node("avatar_morph_check.mjs", q(out("avatar.glb")) + " " + times);
  ASSERT_EQ(j["gaps"].size(), static_cast<std::size_t>(frames));
  EXPECT_EQ(j["mesh"], "Wolf3D_Head");
  std::vector<double> gap;
  for (const auto& g : j["gaps"]) gap.push_back(1000 * g["gap_m"].get<double>());
  int closures = 0, vowels = 0;
  std::string pbm_frames, vowel_frames;
  for (const VisemeRun& run : runs) {
    if (run.end <= run.first || run.end > frames) continue;
    const auto [lo, hi] = std::minmax_element(gap.begin() + run.first, gap.begin() + run.end);
    if (run.viseme == "PP") {  // the lips (nearly) meet during every /p b m/: see spec/rigs.md
      // (1.5 mm, under the 1.4-1.7 mm the lips rest apart on this avatar: since the retargeting's
      // lip-contact term every /p b m/ of this 40-take voice closes to 0.75 mm or less; before it
      // the b b of "Bob bought" reached only 3.34 mm and the sentence's first /m/ 3.11: spec/rigs.md)
      EXPECT_LT(*lo, 1.5) << "PP frames " << run.first << ".." << run.end << ": gaps " << [&] {
        std::string g; for (int f = run.first; f < run.end; ++f) g += std::to_string(gap[static_cast<std::size_t>(f)]) + " "; return g; }();
      ++closures;
      pbm_frames += (closures > 1 ? "," : "") + std::to_string((lo - gap.begin()) / 60.0);
    } else if (is_vowel(run.viseme) && run.end - run.first >= 4) {  // and part for every vowel
      // 4 mm: the calibrated talker's vowels (spec/talker.md) open about half as far as the
      // uncalibrated ones did; a lax /I/ of 4-6 frames reaches 4.7 mm on this avatar.
      EXPECT_GT(*hi, 4.0) << run.viseme << " frames " << run.first << ".." << run.end;
      ++vowels;
      vowel_frames += (vowels > 1 ? "," : "") + std::to_string((hi - gap.begin()) / 60.0);
    }
  }
  EXPECT_GE(closures, 5);
  EXPECT_GE(vowels, 6);
  {  // the closures are small against the vowels' openings
    std::vector<double> closed, open;
    for (const VisemeRun& run : runs) {
      if (run.end <= run.first || run.end > frames) continue;
      const auto [lo, hi] = std::minmax_element(gap.begin() + run.first, gap.begin() + run.end);
      if (run.viseme == "PP") closed.push_back(*lo);
      else if (is_vowel(run.viseme) && run.end - run.first >= 4) open.push_back(*hi);
    }
    std::sort(open.begin(), open.end());
    const double median_open = open[open.size() / 2];
    std::cout << "avatar inner-lip gap (three.js): closures at most " << *std::max_element(closed.begin(), closed.end())
              << " mm, vowels' median opening " << median_open << " mm\n";
    // A quarter: the closures' 2.1 mm is this avatar's known limit (spec/rigs.md), the vowels'
    // median 10 mm since the calibration against real articulography (was 21.6 mm).
    for (double c : closed) EXPECT_LT(c, 0.25 * median_open);
  }
  // rendered by three.js in headless Chromium: the mouth crop is darker (the open mouth) at the
  // vowels' most open frames than at the closures' most closed ones
  const std::string www = out("www");
  fs::create_directories(www);
  fs::copy_file(kViewer + "/avatar_frames.html", www + "/avatar_frames.html");
  fs::create_directory_symlink(kViewer + "/node_modules", www + "/node_modules");
  fs::copy_file(out("avatar.glb"), www + "/avatar.glb");
  // tests/browser/page_result.mjs drives Chromium over the DevTools protocol and waits in real time
  // for the page's result (Chromium's --virtual-time-budget ran out before the loader's callback
  // on a loaded machine, and --dump-dom then printed the page without it).
  const std::string page_command =
      "(cd " + q(www) + " && (python3 -u -m http.server 0 --bind 127.0.0.1 > http.log 2>&1 & echo $! > http.pid) && "
      "for i in $(seq 50); do grep -q 'port' http.log && break; sleep 0.1; done && "
      "port=$(sed -n 's/.* port \\([0-9]*\\).*/\\1/p' http.log | head -1) && " +
      q(FAPCAST_NODE) + " " + q(std::string(FAPCAST_SOURCE_DIR) + "/tests/browser/page_result.mjs") +
      " --chromium " + q(FAPCAST_CHROMIUM) + " --out " + q(www + "/browser") + " --window 1600,400 --seconds 150 "
      "--url \"http://127.0.0.1:$port/avatar_frames.html?glb=/avatar.glb&size=100&times=" + vowel_frames + "," + pbm_frames +
      "\"; status=$?; kill $(cat http.pid); exit $status)";
  const CommandResult page = run_command(page_command);
  ASSERT_EQ(page.exit_code, 0) << page_command << "\n" << page.err;
  const auto result = nlohmann::json::parse(page.out);
  ASSERT_TRUE(result.contains("dark")) << "the page's result: " << page.out;
  const auto dark = result["dark"];
  ASSERT_EQ(dark.size(), static_cast<std::size_t>(vowels + closures));
  double open = 0, shut = 0;
  for (int i = 0; i < vowels; ++i) open += dark[i].get<double>() / vowels;
  for (int i = 0; i < closures; ++i) shut += dark[vowels + i].get<double>() / closures;
  std::cout << "Chromium mouth-crop dark fraction: vowels " << open << ", closures " << shut << "\n";
  EXPECT_GT(open, 1.5 * shut);
}

TEST_F(RigCli, VrmAnimationPlaysInThreeVrm) {
  const auto r = run_command(say("-o " + q(out("say.vrma"))));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = node("vrm_check.mjs", q(std::string(FAPCAST_TEST_DATA) + "/avatars/five-vowels.vrm") + " " + q(out("say.vrma")));
  EXPECT_EQ(j["meta"], "1");
  EXPECT_EQ(j["tracks"], (nlohmann::json{"VRMExpression_aa.weight", "VRMExpression_ih.weight", "VRMExpression_ou.weight",
                                         "VRMExpression_ee.weight", "VRMExpression_oh.weight"}));
  // what three-vrm applies at each key is the file's weight (read here from the .vrma itself)
  const std::string vrma = slurp(out("say.vrma"));
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, vrma.data() + 12, 4);
  const auto doc = nlohmann::json::parse(vrma.substr(20, json_length));
  const char* bin = vrma.data() + 20 + json_length + 8;
  const auto& samplers = doc["animations"][0]["samplers"];
  const std::size_t keys = j["times"].size();
  ASSERT_EQ(keys, doc["accessors"][0]["count"].get<std::size_t>());
  double sum_all = 0;
  for (std::size_t e = 0; e < 5; ++e) {
    const auto& view = doc["bufferViews"][doc["accessors"][samplers[e]["output"].get<int>()]["bufferView"].get<int>()];
    for (std::size_t k = 0; k < keys; ++k) {
      float w = 0;
      std::memcpy(&w, bin + view["byteOffset"].get<std::size_t>() + 12 * k, 4);
      ASSERT_NEAR(j["frames"][k][e].get<double>(), w, 1e-6) << "expression " << e << " key " << k;
      sum_all += w;
    }
  }
  EXPECT_GT(sum_all, 1.0);  // the vowels move
}

// A free UDP port on loopback for a receiver that cannot report the one it bound.
int free_udp_port() {
  const int s = socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t len = sizeof a;
  getsockname(s, reinterpret_cast<sockaddr*>(&a), &len);
  close(s);
  return ntohs(a.sin_port);
}

TEST_F(RigCli, VmcStreamIsDecodedByNodeOscAndOscdump) {
  // node-osc: every frame one bundle, in real time, the CSV's values
  const auto j = node("vmc_osc_check.mjs", q(FAPCAST_EXE) + " say " + q(kText) + " --voice " + q(voice()) +
                                               " -q -o " + q(out("vmc.csv")));
  ASSERT_EQ(j["exit"], 0);
  const auto rows = csv_rows(slurp(out("vmc.csv")));
  const auto& bundles = j["bundles"];
  ASSERT_EQ(bundles.size() + 1, rows.size());
  for (std::size_t f = 0; f < bundles.size(); ++f) {
    const auto& b = bundles[f];
    ASSERT_EQ(b["ok"], 1);
    ASSERT_TRUE(b["apply"].get<bool>() && b["after_apply"] == 0);
    ASSERT_NEAR(b["T"].get<double>(), static_cast<double>(f) / 60, 1e-6);
    ASSERT_EQ(b["names"].size(), 52u);
    for (std::size_t c = 0; c < 52; ++c) {
      ASSERT_EQ(b["names"][c].get<std::string>(), std::string(1, static_cast<char>(std::tolower(rows[0][2 + c][0]))) + rows[0][2 + c].substr(1));
      ASSERT_NEAR(b["values"][c].get<double>(), std::stod(rows[f + 1][2 + c]), 1e-9);
    }
  }
  const double span_s = (bundles.back()["arrival_ms"].get<double>() - bundles.front()["arrival_ms"].get<double>()) / 1000;
  EXPECT_GT(span_s, 0.9 * static_cast<double>(bundles.size() - 1) / 60);  // paced, not a burst
  // liblo's oscdump: the same stream, VRM 0.x names
  const int port = free_udp_port();
  const auto d = run_command("(cd " + q(*dir_) + " && (" + q(FAPCAST_OSCDUMP) + " -L " + std::to_string(port) +
                             " > oscdump.txt 2>&1 & echo $! > oscdump.pid) && sleep 0.3 && " +
                             say("--rig vrm0 -o " + q(out("vmc0.fap")) + " --vmc udp://127.0.0.1:" + std::to_string(port)) +
                             "; status=$?; sleep 0.3; kill $(cat oscdump.pid); exit $status)");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const std::string dump = slurp(out("oscdump.txt"));
  int applies = 0, vals = 0;
  std::istringstream lines(dump);
  for (std::string line; std::getline(lines, line);) {
    applies += line.find("/VMC/Ext/Blend/Apply") != std::string::npos;
    if (line.find("/VMC/Ext/Blend/Val sf \"") != std::string::npos) {
      ++vals;
      const auto name = line.substr(line.find('"') + 1, line.rfind('"') - line.find('"') - 1);
      EXPECT_TRUE(name == "A" || name == "I" || name == "U" || name == "E" || name == "O") << line;
    }
  }
  EXPECT_EQ(applies, static_cast<int>(bundles.size()));
  EXPECT_EQ(vals, 5 * applies);
}

TEST_F(RigCli, RefusesRigOptionsThatDoNotFit) {
  for (const std::string& args : {std::string("--rig vrm -o x.csv"), std::string("--rig nope -o x.csv"),
                                  std::string("--avatar a.glb -o x.csv"), std::string("--rig arkit -o x.fap"),
                                  std::string("--vmc udp://127.0.0.1 -o x.fap"), std::string("-o x.csv --fps 25")}) {
    const auto r = run_command(say(args));
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
  }
  const auto bad = run_command(say("--avatar " + q(std::string(FAPCAST_TEST_DATA) + "/avatars/bad/bad.004.avatar-non-manifold.glb") +
                                   " -o " + q(out("bad.glb"))));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("avatar-non-manifold"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(out("bad.glb")));
}

}  // namespace
}  // namespace fapcast::test
