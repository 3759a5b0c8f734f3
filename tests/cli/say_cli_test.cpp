// `fapcast say` and `fapcast animate` end to end on a voice built from a small SYNTHETIC
// reference corpus: outputs in every format, frame counts on the WAV timeline, and the refusals
// of bad input (exit 1, named) and bad usage (exit 2).
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

#include "fapcast/core/frame_rate.hpp"
#include "fapcast/codec/gltf_export.hpp"
#include "fapcast/corpus/alignment_file.hpp"
#include "fapcast/corpus/alignment_phones.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/facial_expression.hpp"
#include "fapcast/face/obj_mesh.hpp"
#include "fapcast/synthesis/synthesis.hpp"
#include "fapcast/voice/voice.hpp"
#include "fapcast/corpus/lab_file.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/corpus/textgrid.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/transport/track_file.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <filesystem>

namespace fapcast::test {
namespace {

namespace fs = std::filesystem;

// The fixture records 40 script items and builds their voice once per process; CTest runs each
// test in its own process, so the end-to-end checks share one test.
class SayCli : public ::testing::Test {
 public:
  static void SetUpTestSuite() {
    dir_ = new std::string(make_temp_dir("say-cli"));
    const auto r = run_command(fapcast("corpus record-reference -q --count 40 --seed 1 -o " + corpus()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto b = run_command(fapcast("voice build -q " + corpus() + " -o " + voice()));
    ASSERT_EQ(b.exit_code, 0) << b.err;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static std::string corpus() { return *dir_ + "/corpus"; }
  static std::string voice() { return *dir_ + "/v.fapv"; }
  static std::string out(const std::string& name) { return *dir_ + "/" + name; }
  static std::string take(const std::string& ext) { return corpus() + "/utt0003." + ext; }
  static std::string* dir_;
};
std::string* SayCli::dir_ = nullptr;

std::string voice() { return SayCli::voice(); }
std::string out(const std::string& name) { return SayCli::out(name); }
std::string take(const std::string& ext) { return SayCli::take(ext); }

// The frames shown while the audio plays: every j whose first sample (frame_to_sample)
// lies before the audio's end.
std::int64_t frames_for(const Audio& a, std::uint32_t fps) {
  const auto n = static_cast<std::int64_t>(a.samples.size());
  std::int64_t j = 0;
  while (frame_to_sample(j, {fps, 1}, a.sample_rate) < n) ++j;
  return j;
}

void SayWritesTheTrackInSyncWithTheWav() {
  const auto r = run_command(fapcast("say \"Maybe the thin cat will go home.\" --voice " + voice() + " -o " +
                                     out("say.fap") + " --wav-out " + out("say.wav") + " --viseme"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("frames at 25 fps"), std::string::npos) << r.out;
  const Audio audio = read_wav(out("say.wav"));
  const FapSequence seq = read_track_file(out("say.fap"));
  EXPECT_EQ(seq.rate, (FrameRate{25, 1}));
  ASSERT_EQ(static_cast<std::int64_t>(seq.frames.size()), frames_for(audio, 25));
  int jaw_min = 1 << 30, jaw_max = -(1 << 30), tip_max = -(1 << 30);
  bool bilabial = false;
  for (const auto& f : seq.frames) {
    ASSERT_TRUE(f.mask.test(3) && f.mask.test(5) && f.mask.test(44) && f.mask.test(1));
    jaw_min = std::min(jaw_min, f.value(3));
    jaw_max = std::max(jaw_max, f.value(3));
    tip_max = std::max(tip_max, f.value(44));
    bilabial = bilabial || f.viseme.select1 == 1;
  }
  EXPECT_GT(jaw_max - jaw_min, 50) << "the jaw moves";
  EXPECT_GT(tip_max, 250) << "/th t/ lift the tongue tip";
  EXPECT_TRUE(bilabial) << "/m/ shows viseme 1";
  // FAP 1 in the standard layout: the players that read it otherwise are named (spec/fap-text.md).
  EXPECT_NE(r.err.find("note: " + out("say.fap") + ": FAP 1/2 written in the standard layout"), std::string::npos) << r.err;
  // Written for VREng (and Greta): FAP 1 one field, nothing lost (say's visemes are at full
  // weight), no note; read back by fapcast as the same frames.
  const auto vreng = run_command(fapcast("say \"Maybe the thin cat will go home.\" --voice " + voice() + " -o " +
                                         out("say-vreng.fap") + " --viseme --player vreng"));
  ASSERT_EQ(vreng.exit_code, 0) << vreng.err;
  EXPECT_EQ(vreng.err.find("note:"), std::string::npos) << vreng.err;
  EXPECT_EQ(read_track_file(out("say-vreng.fap")).frames, seq.frames);
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" --voice " + voice() + " -o " + out("x.fba") + " --player xface")).exit_code, 2);
}

void EveryFormatAndRate() {
  for (const std::string name : {"a.fba", "a.json", "a.bvh", "b.fap"}) {
    const std::string fps = name == "b.fap" ? " --fps 30" : "";
    const std::string timed = name == "a.json" ? " --duration-weight 0.3" : "";  // the search's duration term
    const auto r = run_command(fapcast("say \"Hello world.\" --voice " + voice() + fps + timed + " --beta 0 --max-active 0 -o " +
                                       out(name) + " --wav-out " + out("hello.wav")));
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
  }
  const Audio audio = read_wav(out("hello.wav"));
  EXPECT_EQ(static_cast<std::int64_t>(read_track_file(out("a.fba")).frames.size()), frames_for(audio, 25));
  EXPECT_EQ(static_cast<std::int64_t>(read_track_file(out("b.fap")).frames.size()), frames_for(audio, 30));
  const auto j = nlohmann::json::parse(read_file(out("a.json")));
  EXPECT_EQ(j["frames"].size(), static_cast<std::size_t>(frames_for(audio, 25)));
  EXPECT_EQ(read_file(out("a.bvh")).rfind("HIERARCHY", 0), 0u);
}

// A text short enough to be one piece: the track made as the speech comes (--piece-seconds 30) is the
// file the whole-text path (--piece-seconds 0, everything at once) writes, byte for byte, in
// every streamed format and option that shapes the frames or the players' notes.
void OnePieceIsTheWholeTextToTheByte() {
  const std::string text = "\"Maybe the thin cat will go home.\" --voice " + voice();
  for (const std::string options : {" --viseme", " --fps 30 --expression joy:40", " --player greta --viseme",
                                    " --fps 60 --beta 0", ""}) {
    for (const std::string ext : {".fap", ".fba", ".json", ".bvh"}) {
      if (ext != ".fap" && options.find("--player") != std::string::npos) continue;
      const auto piece = run_command(fapcast("say " + text + options + " --piece-seconds 30 -o " + out("piece" + ext)));
      const auto whole = run_command(fapcast("say " + text + options + " --piece-seconds 0 -o " + out("whole" + ext)));
      ASSERT_EQ(piece.exit_code, 0) << options << ext << ": " << piece.err;
      ASSERT_EQ(whole.exit_code, 0) << options << ext << ": " << whole.err;
      EXPECT_EQ(piece.out.find("pieces"), std::string::npos) << piece.out;
      EXPECT_TRUE(read_file(out("piece" + ext)) == read_file(out("whole" + ext))) << options << ext;
      auto notes = [](std::string err, const std::string& file) {  // the same notes, for another file name
        for (std::size_t at; (at = err.find(file)) != std::string::npos;) err.replace(at, file.size(), "OUT");
        return err;
      };
      EXPECT_EQ(notes(piece.err, out("piece" + ext)), notes(whole.err, out("whole" + ext))) << options << ext;
    }
  }
}

// A text cut into pieces in its pauses (--piece-seconds 1: at the first pause of 0.25 s after a
// second of speech) against the same text synthesised at once, frame by frame: the WAV is the
// same, the frames are as many, and they differ only where spec/synthesis.md ("Long texts")
// says, by at most what it says.
// The largest FAP difference, pieces against the whole text, of a frame more than 12 frames from
// every pause (PiecesAgainstTheWholeText). Measured 34 FAP units (12 of 168 such frames differ;
// 409 at most near the cuts), Release, spec/synthesis.md "Long texts"; the bound leaves room.
constexpr int kAwayFromCutsFapUnits = 50;

void PiecesAgainstTheWholeText() {
  const std::string text =
      "\"Maybe the thin cat will go home. The big dog sat by the fire, and the fish swam in the sea. "
      "We will be home soon. Move the blue box to the van, please. She saw three ships far away. "
      "Give me the map and the cup.\" --voice " + voice() + " --viseme";
  const auto pieces = run_command(fapcast("say " + text + " --piece-seconds 1 -o " + out("pieces.fap") + " --wav-out " +
                                          out("pieces.wav")));
  const auto whole = run_command(fapcast("say " + text + " --piece-seconds 0 -o " + out("whole.fap") + " --wav-out " +
                                         out("whole.wav")));
  ASSERT_EQ(pieces.exit_code, 0) << pieces.err;
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_NE(pieces.out.find("pieces cut in pauses"), std::string::npos) << pieces.out;
  EXPECT_TRUE(read_file(out("pieces.wav")) == read_file(out("whole.wav")));
  const FapSequence a = read_track_file(out("pieces.fap"));
  const FapSequence b = read_track_file(out("whole.fap"));
  ASSERT_EQ(a.frames.size(), b.frames.size());
  // Where a cut can be: the pauses of at least kPieceCutPauseSeconds (0.25 s), found in the WAV
  // as 10 ms windows of RMS below 100 (espeak-ng's pauses are digital silence).
  const Audio audio = read_wav(out("whole.wav"));
  const std::int64_t window = audio.sample_rate.hz / 100;
  std::vector<std::pair<double, double>> pauses;  // seconds
  std::int64_t quiet_from = -1;
  for (std::int64_t w = 0; (w + 1) * window <= static_cast<std::int64_t>(audio.samples.size()); ++w) {
    double energy = 0.0;
    for (std::int64_t i = w * window; i < (w + 1) * window; ++i) {
      const double x = audio.samples[static_cast<std::size_t>(i)];
      energy += x * x;
    }
    const bool quiet = std::sqrt(energy / static_cast<double>(window)) < 100.0;
    if (quiet && quiet_from < 0) quiet_from = w;
    if (!quiet && quiet_from >= 0) {
      if (w - quiet_from >= 25) pauses.emplace_back(static_cast<double>(quiet_from) * 0.01, static_cast<double>(w) * 0.01);
      quiet_from = -1;
    }
  }
  ASSERT_GE(pauses.size(), 3u) << "the text has pauses to cut in";
  // A frame "near a cut" lies in such a pause or within kNear frames (0.5 s at 25 fps) of one.
  constexpr double kNear = 12;
  const auto near_pause = [&](std::size_t n) {
    const double t = static_cast<double>(n) / 25.0;
    return std::any_of(pauses.begin(), pauses.end(), [&](const std::pair<double, double>& p) {
      return t >= p.first - kNear / 25.0 && t <= p.second + kNear / 25.0;
    });
  };
  std::size_t differ = 0, differ_away = 0, away = 0;
  int largest = 0, largest_away = 0;
  for (std::size_t n = 0; n < a.frames.size(); ++n) {
    ASSERT_EQ(a.frames[n].mask, b.frames[n].mask) << "frame " << n;
    EXPECT_EQ(a.frames[n].viseme, b.frames[n].viseme) << "frame " << n;  // FAP 1 follows the phones alone
    int frame_largest = 0;
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (a.frames[n].mask.test(fap)) frame_largest = std::max(frame_largest, std::abs(a.frames[n].value(fap) - b.frames[n].value(fap)));
    differ += frame_largest > 0;
    largest = std::max(largest, frame_largest);
    if (near_pause(n)) continue;
    ++away;
    differ_away += frame_largest > 0;
    largest_away = std::max(largest_away, frame_largest);
  }
  std::cout << "pieces against the whole text: " << differ << " of " << a.frames.size()
            << " frames differ, by at most " << largest << " FAP units; away from the pauses (" << away
            << " frames more than " << kNear << " frames from any): " << differ_away << " differ, by at most "
            << largest_away << "\n";
  // Away from the pauses the pieces' frames are the whole text's, or near them: the unit search
  // before a cut sees no further than its pause, and a piece's frames count from its start.
  EXPECT_GT(away, a.frames.size() / 3);
  EXPECT_LT(differ_away, away / 4);
  EXPECT_LE(largest_away, kAwayFromCutsFapUnits);
  // The same frames through the other streamed writers.
  ASSERT_EQ(run_command(fapcast("say " + text + " --piece-seconds 1 -o " + out("pieces.fba"))).exit_code, 0);
  EXPECT_EQ(read_track_file(out("pieces.fba")).frames, a.frames);
}

void AnimateFromTextGridAndLab() {
  const Audio audio = read_wav(take("wav"));
  auto r = run_command(fapcast("animate " + take("wav") + " " + take("TextGrid") + " --voice " + voice() +
                               " --fps 60 -o " + out("anim.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(static_cast<std::int64_t>(read_track_file(out("anim.fap")).frames.size()), frames_for(audio, 60));

  // The same phones as a .lab (HTK units), plus a zero-length segment: dropped, not an error.
  const Alignment a = read_textgrid(read_file(take("TextGrid")), take("TextGrid"));
  LabFile lab;
  for (const auto& t : a.tiers)
    if (t.name == "phones") lab.segments = t.intervals;
  ASSERT_FALSE(lab.segments.empty());
  lab.segments.insert(lab.segments.begin() + 1, {lab.segments[1].start_s, lab.segments[1].start_s, "t"});
  lab.scores.assign(lab.segments.size(), std::nullopt);
  write_file_atomically(out("take.lab"), write_lab(lab));
  r = run_command(fapcast("animate " + take("wav") + " " + out("take.lab") + " --voice " + voice() +
                          " -o " + out("anim-lab.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1 phones shorter than a frame dropped"), std::string::npos) << r.out;

  // Shorter than the WAV (its last segment left out): padded with silence and said so.
  LabFile cut = lab;
  cut.segments.pop_back();
  cut.scores.resize(cut.segments.size());
  write_file_atomically(out("short.lab"), write_lab(cut));
  r = run_command(fapcast("animate " + take("wav") + " " + out("short.lab") + " --voice " + voice() +
                          " -o " + out("short.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_EQ(static_cast<std::int64_t>(read_track_file(out("short.fap")).frames.size()), frames_for(audio, 25));

  // Longer than the WAV by a second: refused.
  LabFile longer = lab;
  const double end = longer.segments.back().end_s;
  longer.segments.push_back({end, end + 1.0, "sil"});
  longer.scores.push_back(std::nullopt);
  write_file_atomically(out("long.lab"), write_lab(longer));
  r = run_command(fapcast("animate " + take("wav") + " " + out("long.lab") + " --voice " + voice() +
                          " -o " + out("long.fap")));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("alignment-longer-than-audio"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("long.fap")));
}

// Alignment files written by other tools (tests/data/speech): EMU's grid with an empty first tier,
// a stereo WAV; and the take's own phones in TIMIT's layout (sample offsets), as a .phn and renamed
// .lab (refused with both readings).
void AnimateRealAlignments() {
  const fs::path speech = fs::path(FAPCAST_TEST_DATA) / "speech";
  const Audio audio = read_wav(take("wav"));
  const AlignmentFile grid_phones = read_alignment_file(read_file(take("TextGrid")), take("TextGrid"), {});
  std::string phn;
  std::size_t phones = 0;
  for (const AlignedSegment& s : grid_phones.segments) {
    std::string label = s.kind == LabelKind::silence ? "h#" : s.label;
    std::erase_if(label, [](char c) { return c >= '0' && c <= '9'; });  // TIMIT labels carry no stress
    std::transform(label.begin(), label.end(), label.begin(), [](unsigned char c) { return std::tolower(c); });
    phones += s.kind == LabelKind::phone;
    phn += std::to_string(to_sample(s.start_s, audio.sample_rate)) + " " +
           std::to_string(to_sample(s.end_s, audio.sample_rate)) + " " + label + "\n";
  }
  write_file_atomically(out("take.phn"), phn);
  auto r = run_command(fapcast("animate " + take("wav") + " " + out("take.phn") + " --voice " + voice() + " -o " +
                               out("timit.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("take.phn: labels: timit (" + std::to_string(phones) + " phones)"), std::string::npos) << r.err;
  EXPECT_EQ(static_cast<std::int64_t>(read_track_file(out("timit.fap")).frames.size()), frames_for(audio, 25));

  write_file_atomically(out("take-phn.lab"), phn);
  r = run_command(fapcast("animate " + take("wav") + " " + out("take-phn.lab") + " --voice " + voice() + " -o " +
                          out("renamed.fap")));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("take-phn.lab: lab-units-mismatch: as HTK 100 ns units (what a .lab holds) the segments end at "),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("renamed.fap")));

  const std::string emu = (speech / "emu-ae/msajc003").string();
  r = run_command(fapcast("animate " + emu + ".wav " + emu + ".TextGrid --voice " + voice() + " -o " +
                          out("emu.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("tier \"Phonetic\" of 11 (by its name)"), std::string::npos) << r.err;
  r = run_command(fapcast("animate " + emu + ".wav " + emu + ".TextGrid --tier Utterance --voice " +
                          voice() + " -o " + out("emu-utt.fap")));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("alignment-no-phones: tier \"Utterance\" has no phone"), std::string::npos) << r.err;

  // MOCHA-TIMIT's own label file and recording (fsew0_001), read in its own label set.
  const std::string mocha = std::string(FAPCAST_TEST_DATA) + "/mocha/fsew0_001";
  r = run_command(fapcast("animate " + mocha + ".wav " + mocha + ".lab --voice " + voice() + " -o " + out("mocha.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("labels: mocha (14 phones)"), std::string::npos) << r.err;
  EXPECT_EQ(static_cast<std::int64_t>(read_track_file(out("mocha.fap")).frames.size()),
            frames_for(read_wav(mocha + ".wav"), 25));

  // praatIO's stereo recording of "bobby ripped the ledger" with its phone grid, whose one typo
  // ("PT" for the P T of "ripped") is written out here as T.
  std::string grid = read_file(speech / "praatio/bobby_phones.TextGrid");
  grid.replace(grid.find("\"PT\""), 4, "\"T\"");
  write_file_atomically(out("bobby.TextGrid"), grid);
  r = run_command(fapcast("animate " + (speech / "stereo/bobby_16bit_16khz_2ch.wav").string() + " " +
                          out("bobby.TextGrid") + " --voice " + voice() + " -o " + out("stereo.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("bobby_16bit_16khz_2ch.wav: 2 channels downmixed to mono"), std::string::npos) << r.err;
}

// Recorded speech with its transcript only: the forced aligner finds the phones (spec/recognise.md);
// --alignment-out writes what it found as a TextGrid that reads back with the two tiers.
void AnimateFromTranscript() {
  const std::string emu = std::string(FAPCAST_TEST_DATA) + "/speech/emu-ae/msajc003";
  auto r = run_command(fapcast("animate " + emu + ".wav --transcript " + emu + ".txt --voice " + voice() + " -o " +
                               out("emu-aligned.fap") + " --alignment-out " + out("emu-aligned.TextGrid")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Audio audio = read_wav(emu + ".wav");
  EXPECT_EQ(static_cast<std::int64_t>(read_track_file(out("emu-aligned.fap")).frames.size()), frames_for(audio, 25));
  AlignmentFileOptions options;
  options.sample_rate = audio.sample_rate;
  const AlignmentFile found = read_alignment_file(read_file(out("emu-aligned.TextGrid")), "emu-aligned.TextGrid", options);
  EXPECT_EQ(found.tier, "phones");
  const LabelTier* words = found.alignment.find("words");
  ASSERT_NE(words, nullptr);
  std::string said;
  for (const Interval& i : words->intervals)
    if (!i.label.empty()) said += (said.empty() ? "" : " ") + i.label;
  EXPECT_EQ(said, "amongst her friends she was considered beautiful");
  // The same words as --text: the same animation.
  r = run_command(fapcast("animate " + emu + ".wav --text \"amongst her friends she was considered beautiful\" --voice " +
                          voice() + " -o " + out("emu-text.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(out("emu-text.fap")), read_file(out("emu-aligned.fap")));
  // Another recording's words: refused, naming the recording (exit 1), nothing written.
  r = run_command(fapcast("animate " + emu + ".wav --text \"it is futile to offer any further resistance\" --voice " +
                          voice() + " -o " + out("emu-wrong.fap")));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("msajc003.wav: no-speech: "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("emu-wrong.fap")));
  // No transcript at all: the words are recognised, then aligned; the animation spans the recording
  // and the words heard are noted with their confidence.
  r = run_command(fapcast("animate " + emu + ".wav --voice " + voice() + " -o " + out("emu-heard.fap") +
                          " --alignment-out " + out("emu-heard.TextGrid")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("msajc003.wav: no transcript: recognised "), std::string::npos) << r.err;
  EXPECT_EQ(static_cast<std::int64_t>(read_track_file(out("emu-heard.fap")).frames.size()), frames_for(audio, 25));
  const AlignmentFile heard = read_alignment_file(read_file(out("emu-heard.TextGrid")), "emu-heard.TextGrid", options);
  std::string heard_words;
  for (const Interval& i : heard.alignment.find("words")->intervals)
    if (!i.label.empty()) heard_words += (heard_words.empty() ? "" : " ") + i.label;
  EXPECT_NE(heard_words.find("considered beautiful"), std::string::npos) << heard_words;
}

void BadInputExitsOneAndNamesIt() {
  auto expect_error = [](const std::string& args, const std::string& what) {
    const auto r = run_command(fapcast(args));
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << args << "\n" << r.err;
  };
  expect_error("say \"   \" --voice " + voice() + " -o " + out("e.fap"), "empty-text");
  expect_error("animate " + out("none.wav") + " " + take("TextGrid") + " --voice " + voice() +
                   " -o " + out("e.fap"), "none.wav");
  expect_error("animate " + take("wav") + " " + out("none.lab") + " --voice " + voice() +
                   " -o " + out("e.fap"), "none.lab");
  write_file_atomically(out("bad.lab"), "0 1000000 sil\n1000000 2000000 xyz\n");
  expect_error("animate " + take("wav") + " " + out("bad.lab") + " --voice " + voice() + " -o " +
                   out("e.fap"), "alignment-unknown-label");
  write_file_atomically(out("overlap.lab"), "0 2000000 sil\n1000000 3000000 aa\n");
  expect_error("animate " + take("wav") + " " + out("overlap.lab") + " --voice " + voice() + " -o " +
                   out("e.fap"), "overlap.lab");
  // A time no sample count can hold is the alignment's fault (exit 1), not an internal error.
  write_file_atomically(out("huge.lab"), "0 1e300 aa\n");
  expect_error("animate " + take("wav") + " " + out("huge.lab") + " --voice " + voice() + " -o " + out("e.fap"),
               "huge.lab: time-off-sample-grid: segment 1 'aa': time 1e+300 s is off the sample grid of 22050 Hz");
  write_file_atomically(out("not-a-voice.fapv"), "this is not a voice\n");
  expect_error("say \"Hello.\" --voice " + out("not-a-voice.fapv") + " -o " + out("e.fap"), "not-a-voice.fapv");
  expect_error("say \"Hello.\" --voice " + out("missing.fapv") + " -o " + out("e.fap"), "missing.fapv");
  EXPECT_FALSE(fs::exists(out("e.fap")));
}

// The take's phones as `animate` reads them, synthesised by the library with the CLI's defaults.
SynthesizedTrack library_track(const Voice& v, const Audio& audio) {
  const AlignmentFile a = read_alignment_file(read_file(take("TextGrid")), take("TextGrid"), {});
  const auto samples = audio.instants();
  const auto phones = fit_phones_to_audio(timed_phones(a.segments, audio.sample_rate, "t"), samples,
                                          audio.sample_rate.hz / 50, "t");
  const SynthesisOptions options;  // the library's defaults, which `animate` ships
  return synthesize(v, phones, audio.sample_rate, samples, options, "t");
}

double mean_fap(const FapSequence& seq, int fap) {
  double sum = 0;
  for (const auto& f : seq.frames) sum += f.value(fap);
  return sum / static_cast<double>(seq.frames.size());
}

// --expression: FAP 2 in every frame of .fap and .fba, and the lips' FAPs come from the blended
// face: joy pulls the lip corners outwards and up.
void ExpressionBlendsWithSpeech() {
  const std::string animate = "animate " + take("wav") + " " + take("TextGrid") + " --voice " + voice();
  auto r = run_command(fapcast(animate + " -o " + out("plain.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string name : {"joy.fap", "joy.fba"}) {
    r = run_command(fapcast(animate + " --expression joy:63 -o " + out(name)));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_NE(r.out.find("expression joy:63"), std::string::npos) << r.out;
  const auto plain = read_track_file(out("plain.fap"));
  for (const std::string name : {"joy.fap", "joy.fba"}) {
    SCOPED_TRACE(name);
    const auto joy = read_track_file(out(name));
    ASSERT_EQ(joy.frames.size(), plain.frames.size());
    for (const auto& f : joy.frames) {
      ASSERT_TRUE(f.mask.test(2));
      ASSERT_EQ(f.expression.select1, 1);  // joy
      ASSERT_EQ(f.expression.intensity1, 63);
      ASSERT_EQ(f.expression.select2, 0);
    }
    for (const int fap : {53, 54, 59, 60}) {  // stretch / raise the outer lip corners 8.3, 8.4
      ASSERT_TRUE(joy.frames[0].mask.test(fap)) << fap;
      EXPECT_GT(mean_fap(joy, fap), mean_fap(plain, fap) + 20) << "FAP " << fap;
    }
    EXPECT_FALSE(plain.frames[0].mask.test(2));
  }
  // Two expressions: both fields.
  r = run_command(fapcast(animate + " --expression joy:40,surprise:20 -o " + out("two.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto two = read_track_file(out("two.fap"));
  EXPECT_EQ(two.frames[0].expression, (ExpressionField{1, 40, 6, 20, false, false}));
}

// -o OUT.glb: the voice's mean is the mesh, its k components the targets, the synthesised PCA
// frames the weights at 60 fps; --expression adds one target with weight 1; three.js loads it.
void GlbCarriesThePcaFrames() {
  const Voice v = Voice::open(voice());
  const Audio audio = read_wav(take("wav"));
  const std::string animate = "animate " + take("wav") + " " + take("TextGrid") + " --voice " + voice();
  auto r = run_command(fapcast(animate + " -o " + out("anim.glb")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("frames at 60 fps"), std::string::npos) << r.out;
  const auto a = read_glb(read_file(out("anim.glb")), out("anim.glb"));
  const auto k = static_cast<std::size_t>(v.component_count());
  ASSERT_EQ(a.targets_m.size(), k);
  EXPECT_EQ(a.target_names.front(), "pc1");
  EXPECT_EQ(a.rate, (FrameRate{60, 1}));
  const Eigen::Index n = v.dimension() / 3;
  EXPECT_EQ(a.base_positions_m, Eigen::Map<const Eigen::Matrix3Xf>(v.pca_mean().data(), 3, n));
  for (std::size_t i = 0; i < k; ++i) {
    const Eigen::Matrix<float, 1, Eigen::Dynamic> row = v.pca_components().row(static_cast<Eigen::Index>(i));
    ASSERT_EQ(a.targets_m[i], Eigen::Map<const Eigen::Matrix3Xf>(row.data(), 3, n)) << "component " << i;
  }
  const SynthesizedTrack track = library_track(v, audio);
  ASSERT_EQ(a.weights.rows(), frames_for(audio, 60));
  ASSERT_LE(a.weights.rows(), track.pca_frames.rows());
  EXPECT_EQ(a.weights, track.pca_frames.topRows(a.weights.rows())) << "the weights are the PCA frames, bit for bit";
  EXPECT_EQ(a.triangles, triangulate(ict_face_model().faces));

  r = run_command(fapcast(animate + " --expression joy:40 -o " + out("joy.glb")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = read_glb(read_file(out("joy.glb")), out("joy.glb"));
  ASSERT_EQ(j.targets_m.size(), k + 1);
  EXPECT_EQ(j.target_names.back(), "joy:40");
  EXPECT_TRUE((j.weights.col(static_cast<Eigen::Index>(k)).array() == 1.0f).all());
  EXPECT_EQ(j.weights.leftCols(static_cast<Eigen::Index>(k)), a.weights);
  const Positions joy_m =
      0.01f * expression_displacement(ict_face_model(), {Expression::joy, 40});
  EXPECT_LT((j.targets_m.back() - joy_m).cwiseAbs().maxCoeff(), 1e-9f);

  // say: the WAV goes beside the .glb.
  r = run_command(fapcast("say \"Hello.\" --voice " + voice() + " --expression joy:40 -o " + out("hello.glb") +
                          " --obj-frames-out " + out("hello-obj")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Audio hello = read_wav(out("hello.wav"));
  const auto h = read_glb(read_file(out("hello.glb")), "hello.glb");
  EXPECT_EQ(h.weights.rows(), frames_for(hello, 60));
  // --obj-frames-out: every frame as an OBJ of the mesh the .glb shows.
  std::size_t objs = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out("hello-obj"))) ++objs;
  EXPECT_EQ(objs, static_cast<std::size_t>(h.weights.rows()));
  const auto frame5 = read_obj_mesh(out("hello-obj") + "/frame_000005.obj");
  EXPECT_LT((frame5.vertices - frame_positions(h, 5)).cwiseAbs().maxCoeff(), 1e-7f);

  // A standard viewer: three.js's GLTFLoader (Debian libjs-three) in Node sees k + 1 morph
  // targets and one morphTargetInfluences track with a key per frame, holding the file's weights.
  const std::string script = std::string(FAPCAST_SOURCE_DIR) + "/tests/viewer/three_gltf_check.js";
  r = run_command("node '" + script + "' '" + out("hello.glb") + "' --targets " + std::to_string(k + 1) +
                  " --frames " + std::to_string(h.weights.rows()) + " --fps 60");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto seen = nlohmann::json::parse(r.out);
  EXPECT_EQ(seen["vertices"], n);
  EXPECT_EQ(seen["names"].front(), "pc1");
  EXPECT_EQ(seen["names"].back(), "joy:40");
  const auto& track0 = seen["animations"][0]["tracks"][0];
  ASSERT_EQ(track0["weights"].size(), static_cast<std::size_t>(h.weights.size()));
  for (Eigen::Index f = 0; f < h.weights.rows(); ++f)
    for (Eigen::Index c = 0; c <= static_cast<Eigen::Index>(k); ++c)
      ASSERT_EQ(track0["weights"][static_cast<std::size_t>(f * (static_cast<Eigen::Index>(k) + 1) + c)].get<float>(),
                h.weights(f, c))
          << "frame " << f << ", target " << c;
}

// voice adapt: on a face 1.5 times the generic one (moved), every displacement is 1.5 times
// the generic one and the FAPs (displacements over the face's own FAPU) stay the same; on an
// actor made of ICT identity shapes the voice speaks and its FAPU are the actor's.
void AdaptedVoiceSpeaks() {
  const std::string ict = std::string(FAPCAST_SOURCE_DIR) + "/data/ict-facekit/generic_neutral_mesh.obj";
  const ObjMesh generic = read_obj_mesh(ict);
  const Positions big = (1.5f * generic.vertices).colwise() + Eigen::Vector3f(1, 2, 3);
  write_file_atomically(out("big.obj"), write_obj_mesh(big, generic.faces));
  auto r = run_command(fapcast("voice adapt " + voice() + " '" + ict + "' " + out("big.obj") + " -o " +
                               out("big.fapv")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("components adapted"), std::string::npos) << r.out;
  const std::string animate = "animate " + take("wav") + " " + take("TextGrid");
  for (const std::string v : {"v", "big"}) {
    r = run_command(fapcast(animate + " --voice " + out(v + ".fapv") + " -o " + out("rt-" + v + ".fap")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run_command(fapcast(animate + " --voice " + out(v + ".fapv") + " -o " + out("rt-" + v + ".glb")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const auto g = read_track_file(out("rt-v.fap")), s = read_track_file(out("rt-big.fap"));
  ASSERT_EQ(g.frames.size(), s.frames.size());
  int worst = 0;
  for (std::size_t f = 0; f < g.frames.size(); ++f) {
    ASSERT_EQ(g.frames[f].mask, s.frames[f].mask);
    for (int fap = 3; fap <= 68; ++fap)
      if (g.frames[f].mask.test(fap)) worst = std::max(worst, std::abs(g.frames[f].value(fap) - s.frames[f].value(fap)));
  }
  EXPECT_LE(worst, 1) << "FAPs are in the face's own units: a scaled face plays the same values (+-1 rounding)";
  const auto gg = read_glb(read_file(out("rt-v.glb")), "rt-v.glb");
  const auto sg = read_glb(read_file(out("rt-big.glb")), "rt-big.glb");
  ASSERT_EQ(gg.targets_m.size(), sg.targets_m.size());
  const Eigen::Matrix3Xf generic_m = 0.01f * generic.vertices, big_m = 0.01f * big;
  EXPECT_LT((sg.base_positions_m - (big_m + 1.5f * (gg.base_positions_m - generic_m))).cwiseAbs().maxCoeff(), 1e-5f);
  for (std::size_t i = 0; i < gg.targets_m.size(); ++i)  // the components (expressions: speech_expression_test)
    EXPECT_LT((sg.targets_m[i] - 1.5f * gg.targets_m[i]).cwiseAbs().maxCoeff(), 1e-6f) << "target " << i;
  EXPECT_EQ(sg.weights, gg.weights) << "the PCA frames are the voice's, unchanged";

  // An actor from three ICT identity shapes: the voice speaks with the actor's FAPU.
  const FaceModel& face = ict_face_model();
  Positions actor = face.neutral_cm;
  for (std::size_t i = 0; i < 3; ++i) add_scaled(actor, face.identities[i], i == 1 ? -0.8f : 0.9f);
  write_file_atomically(out("actor.obj"), write_obj_mesh(actor, face.faces));
  r = run_command(fapcast("voice adapt " + voice() + " '" + ict + "' " + out("actor.obj") + " -o " +
                          out("actor.fapv")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_command(fapcast(animate + " --voice " + out("actor.fapv") + " -o " + out("rt-actor.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_command(fapcast("say \"Hello.\" --voice " + out("actor.fapv") + " -o " + out("actor-say.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(read_track_file(out("actor-say.fap")).frames.size(), 5u);
  const Voice actor_voice = Voice::open(out("actor.fapv"));
  for (const auto& p : actor_voice.feature_points())
    ASSERT_LT((p.neutral_m - 0.01 * actor.col(p.vertex).cast<double>()).norm(), 1e-7) << p.label;
  const auto a = read_track_file(out("rt-actor.fap"));
  ASSERT_EQ(a.frames.size(), g.frames.size());
  int differ = 0;
  for (std::size_t f = 0; f < g.frames.size(); ++f) differ += g.frames[f].value(3) != a.frames[f].value(3);
  EXPECT_GT(differ, 0) << "another face: other displacements and other FAPU";

  // Bad input: the generic mesh in the wrong unit names the rule and the feature point.
  r = run_command(fapcast("voice adapt " + voice() + " '" + ict + "' " + out("big.obj") + " --obj-unit m -o " +
                          out("bad.fapv")));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("generic-mismatch"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("bad.fapv")));
}

// Issue #17, attack 10: a failed `say -o x.glb` left the WAV without its .glb. Both appear or
// neither: here the .glb cannot be renamed into place (a directory is in the way).
void AFailedGlbLeavesNoWav() {
  fs::create_directories(out("blocked.glb") + "/in-the-way");
  const auto r = run_command(fapcast("say \"Hi.\" --voice " + voice() + " -o " + out("blocked.glb")));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("blocked.glb"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("blocked.wav")));
  for (const auto& e : fs::directory_iterator(fs::path(out(""))))
    EXPECT_EQ(e.path().filename().string().find("tmp"), std::string::npos) << e.path();
}

// The text from TEXT, standard input (-) or --text-file gives the same speech (a fresh process
// making the same espeak-ng calls reproduces its output exactly); --lang speaks Russian; SSML
// markup is parsed (a 1 s break lengthens the speech), not read out.
void SayReadsFilesStdinLanguagesAndSsml() {
  const std::string text = "Hello there.";
  const std::string common = " --voice " + voice() + " -q --viseme -o " + out("text.fap");
  auto r = run_command(fapcast("say \"" + text + "\"" + common + " --wav-out " + out("arg.wav")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  write_file_atomically(out("text.txt"), text);
  r = run_command(fapcast("say --text-file " + out("text.txt") + common + " --wav-out " + out("file.wav")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // In a subshell: run_command's </dev/null then applies to the subshell, not to the pipe's end.
  r = run_command("(printf '" + text + "' | " + fapcast("say -" + common + " --wav-out " + out("stdin.wav")) + ")");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Audio arg = read_wav(out("arg.wav"));
  EXPECT_EQ(read_wav(out("file.wav")).samples, arg.samples);
  EXPECT_EQ(read_wav(out("stdin.wav")).samples, arg.samples);
  r = run_command(fapcast("say --ssml '<speak>Hello <break time=\"1s\"/> there.</speak>'" + common +
                          " --wav-out " + out("ssml.wav")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Audio ssml = read_wav(out("ssml.wav"));
  EXPECT_GT(ssml.samples.size(), arg.samples.size() + static_cast<std::size_t>(arg.sample_rate.hz * 8 / 10));
  EXPECT_LT(ssml.samples.size(), arg.samples.size() + static_cast<std::size_t>(arg.sample_rate.hz * 2));
  r = run_command(fapcast("say --lang ru 'Москва' --espeak-variant f2" + common));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(read_track_file(out("text.fap")).frames.empty());
}

TEST_F(SayCli, SayAndAnimateEndToEnd) {
  {
    SCOPED_TRACE("SayReadsFilesStdinLanguagesAndSsml");
    SayReadsFilesStdinLanguagesAndSsml();
  }
  {
    SCOPED_TRACE("SayWritesTheTrackInSyncWithTheWav");
    SayWritesTheTrackInSyncWithTheWav();
  }
  {
    SCOPED_TRACE("EveryFormatAndRate");
    EveryFormatAndRate();
  }
  {
    SCOPED_TRACE("OnePieceIsTheWholeTextToTheByte");
    OnePieceIsTheWholeTextToTheByte();
  }
  {
    SCOPED_TRACE("PiecesAgainstTheWholeText");
    PiecesAgainstTheWholeText();
  }
  {
    SCOPED_TRACE("AnimateFromTextGridAndLab");
    AnimateFromTextGridAndLab();
  }
  {
    SCOPED_TRACE("AnimateRealAlignments");
    AnimateRealAlignments();
  }
  {
    SCOPED_TRACE("AnimateFromTranscript");
    AnimateFromTranscript();
  }
  {
    SCOPED_TRACE("BadInputExitsOneAndNamesIt");
    BadInputExitsOneAndNamesIt();
  }
  {
    SCOPED_TRACE("ExpressionBlendsWithSpeech");
    ExpressionBlendsWithSpeech();
  }
  {
    SCOPED_TRACE("GlbCarriesThePcaFrames");
    GlbCarriesThePcaFrames();
  }
  {
    SCOPED_TRACE("AdaptedVoiceSpeaks");
    AdaptedVoiceSpeaks();
  }
  {
    SCOPED_TRACE("AFailedGlbLeavesNoWav");
    AFailedGlbLeavesNoWav();
  }
}

// An option the command does not have is answered with the command's options near it in spelling
// and, when none is near, with its positional inputs (cli/usage_hints.hpp): the spellings of
// other tools and of older commands ("--wav", "--align", "--obj-frames") find their way.
TEST(SayCliUsage, AnUnknownOptionIsAnsweredWithTheNearOnesOrThePositionals) {
  const auto a = run_command(fapcast("animate --wav a.wav --align a.TextGrid -o x.fap"));
  EXPECT_EQ(a.exit_code, 2);
  EXPECT_NE(a.err.find("fapcast: hint: --wav is not an option of 'animate'\n"), std::string::npos) << a.err;
  EXPECT_NE(a.err.find("fapcast: hint: its inputs are positional: fapcast animate SPEECH [ALIGNMENT]\n"),
            std::string::npos) << a.err;
  const auto g = run_command(fapcast("say \"Hi.\" -o x.glb --obj-frames d"));
  EXPECT_EQ(g.exit_code, 2);
  EXPECT_NE(g.err.find("--obj-frames is not an option of 'say'; did you mean --obj-frames-out?"), std::string::npos)
      << g.err;
  EXPECT_EQ(g.err.find("positional"), std::string::npos) << "a near option says enough: " << g.err;
  const auto f = run_command(fapcast("fap info --jsn=1 x.fap"));
  EXPECT_EQ(f.exit_code, 2);
  EXPECT_NE(f.err.find("--jsn is not an option of 'fap info'; did you mean --json?"), std::string::npos) << f.err;
  const auto e = run_command(fapcast("eval articulography --ema x.ema"));
  EXPECT_EQ(e.exit_code, 2);
  EXPECT_NE(e.err.find("fapcast eval articulography EMA SPEECH [ALIGNMENT]"), std::string::npos) << e.err;
  // A mistake that is not an unknown option gets no hint.
  const auto s = run_command(fapcast("say \"Hi.\" -o x.fap --fps 0"));
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_EQ(s.err.find("hint"), std::string::npos) << s.err;
}

TEST(SayCliUsage, MistakesExitTwo) {
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.txt --voice v.fapv")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("say \"Hi.\"")).exit_code, 2);  // no -o
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.fap --fps 0")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.fap --fps 500")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.fap --duration-weight -1")).exit_code, 2);
  // no alignment and no transcript: what the speech says is recognised (a WAV that is not there: exit 1)
  EXPECT_EQ(run_command(fapcast("animate a.wav -o x.fap")).exit_code, 1);
  // The phones come from one place: an alignment, a transcript file or a text.
  EXPECT_EQ(run_command(fapcast("animate a.wav a.TextGrid --transcript a.txt -o x.fap")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("animate a.wav --transcript a.txt --text \"hi\" -o x.fap")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("animate a.wav a.TextGrid --alignment-out b.TextGrid -o x.fap")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("animate a.wav --text \"hi\" --alignment-out b.lab -o x.fap")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("animate a.wav --text \"hi\" --tier phones -o x.fap")).exit_code, 2);
  // One meaning per option name: --wav is an input WAV (stream's); say writes its speech with --wav-out.
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.fap --wav x.wav")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("animate --wav a.wav --align a.TextGrid -o x.fap")).exit_code, 2);
  // The alignment's format comes from its content (a .txt name is fine): an unknown label set is
  // the usage mistake.
  EXPECT_EQ(run_command(fapcast("animate a.wav a.txt --phone-set klingon -o x.fap")).exit_code, 2);
  // Expressions: an unknown name or an intensity outside 0..63 is a usage mistake, said clearly.
  for (const std::string bad : {"glee:40", "joy:64", "joy:40,fear:10,anger:5"}) {
    const auto r = run_command(fapcast("say \"Hi.\" -o x.fap --voice v.fapv --expression " + bad));
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("--expression"), std::string::npos) << r.err;
  }
  EXPECT_NE(run_command(fapcast("say \"Hi.\" -o x.fap --expression glee")).err.find("joy, sadness"), std::string::npos);
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.glb --fps 25")).exit_code, 2);  // .glb keys are the voice's 60 fps
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.glb --viseme")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.fap --obj-frames-out d")).exit_code, 2);  // OBJ frames: .glb only
  // Pieces are for FAP tracks: a .glb, a rig or cues alone are made whole, so a piece length is refused.
  for (const std::string whole : {"-o x.glb", "-o x.csv --rig arkit", "--cues-out x.tsv"}) {
    const auto r = run_command(fapcast("say \"Hi.\" " + whole + " --piece-seconds 10"));
    EXPECT_EQ(r.exit_code, 2) << whole;
    EXPECT_NE(r.err.find("--piece-seconds applies to a FAP track"), std::string::npos) << r.err;
  }
  EXPECT_EQ(run_command(fapcast("voice adapt v.fapv g.obj -o v2.fapv")).exit_code, 2);  // no specific face
  // The text comes from one place; --lang and --espeak-variant name what espeak-ng has.
  EXPECT_EQ(run_command(fapcast("say -o x.fap --voice v.fapv")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" --text-file a.txt -o x.fap --voice v.fapv")).exit_code, 2);
  const auto lang = run_command(fapcast("say \"Hi.\" --lang klingon -o x.fap --voice v.fapv"));
  EXPECT_EQ(lang.exit_code, 2);
  EXPECT_NE(lang.err.find("--lang 'klingon': not an installed espeak-ng language"), std::string::npos) << lang.err;
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" --espeak-variant zz -o x.fap --voice v.fapv")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("say --text-file /nonexistent/a.txt -o x.fap --voice v.fapv")).exit_code, 1);
  // A bad byte in a text file is bad input named by file and byte offset (before any voice).
  const std::string bad = make_temp_dir("say-usage") + "/bad.txt";
  write_file_atomically(bad, std::string("Hello\x01 there."));
  const auto r = run_command(fapcast("say --text-file " + bad + " -o x.fap --voice v.fapv"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(bad + ": byte 5: control-character"), std::string::npos) << r.err;
  fs::remove_all(fs::path(bad).parent_path());
}

}  // namespace
}  // namespace fapcast::test
