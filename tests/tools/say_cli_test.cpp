// `fapcast say` and `fapcast animate` end to end on a voice built from a small SYNTHETIC
// reference corpus: outputs in every format, frame counts on the WAV timeline, and the refusals
// of bad input (exit 1, named) and bad usage (exit 2).
#include "support/run_command.hpp"

#include "fapcast/codec/frame_rate.hpp"
#include "fapcast/synth/lab_file.hpp"
#include "fapcast/synth/mono_audio.hpp"
#include "fapcast/synth/textgrid.hpp"
#include "fapcast/transport/file_io.hpp"
#include "fapcast/transport/track_file.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

// The frames shown while the audio plays: every j whose first sample (codec::frame_to_sample)
// lies before the audio's end.
std::int64_t frames_for(const synth::MonoAudio& a, std::uint32_t fps) {
  const auto n = static_cast<std::int64_t>(a.samples.size());
  std::int64_t j = 0;
  while (codec::frame_to_sample(j, {fps, 1}, a.sample_rate_hz) < n) ++j;
  return j;
}

void SayWritesTheTrackInSyncWithTheWav() {
  const auto r = run_command(fapcast("say \"Maybe the thin cat will go home.\" --voice " + voice() + " -o " +
                                     out("say.fap") + " --wav " + out("say.wav") + " --viseme"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("frames at 25 fps"), std::string::npos) << r.out;
  const synth::MonoAudio audio = synth::read_wav(out("say.wav"));
  const codec::FapSequence seq = transport::read_track_file(out("say.fap"));
  EXPECT_EQ(seq.rate, (codec::FrameRate{25, 1}));
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
}

void EveryFormatAndRate() {
  for (const std::string name : {"a.fba", "a.json", "a.bvh", "b.fap"}) {
    const std::string fps = name == "b.fap" ? " --fps 30" : "";
    const auto r = run_command(fapcast("say \"Hello world.\" --voice " + voice() + fps + " --beta 0 --max-active 0 -o " +
                                       out(name) + " --wav " + out("hello.wav")));
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
  }
  const synth::MonoAudio audio = synth::read_wav(out("hello.wav"));
  EXPECT_EQ(static_cast<std::int64_t>(transport::read_track_file(out("a.fba")).frames.size()), frames_for(audio, 25));
  EXPECT_EQ(static_cast<std::int64_t>(transport::read_track_file(out("b.fap")).frames.size()), frames_for(audio, 30));
  const auto j = nlohmann::json::parse(transport::read_file(out("a.json")));
  EXPECT_EQ(j["frames"].size(), static_cast<std::size_t>(frames_for(audio, 25)));
  EXPECT_EQ(transport::read_file(out("a.bvh")).rfind("HIERARCHY", 0), 0u);
}

void AnimateFromTextGridAndLab() {
  const synth::MonoAudio audio = synth::read_wav(take("wav"));
  auto r = run_command(fapcast("animate --wav " + take("wav") + " --align " + take("TextGrid") + " --voice " + voice() +
                               " --fps 60 -o " + out("anim.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(static_cast<std::int64_t>(transport::read_track_file(out("anim.fap")).frames.size()), frames_for(audio, 60));

  // The same phones as a .lab (HTK units), plus a zero-length segment: dropped, not an error.
  const synth::Alignment a = synth::read_textgrid(transport::read_file(take("TextGrid")), take("TextGrid"));
  synth::LabFile lab;
  for (const auto& t : a.tiers)
    if (t.name == "phones") lab.segments = t.intervals;
  ASSERT_FALSE(lab.segments.empty());
  lab.segments.insert(lab.segments.begin() + 1, {lab.segments[1].start_s, lab.segments[1].start_s, "t"});
  lab.scores.assign(lab.segments.size(), std::nullopt);
  transport::write_file_atomically(out("take.lab"), synth::write_lab(lab));
  r = run_command(fapcast("animate --wav " + take("wav") + " --align " + out("take.lab") + " --voice " + voice() +
                          " -o " + out("anim-lab.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1 phones shorter than a frame dropped"), std::string::npos) << r.out;

  // Shorter than the WAV: padded with silence and said so.
  synth::LabFile cut = lab;
  cut.segments.resize(cut.segments.size() / 2);
  cut.scores.resize(cut.segments.size());
  transport::write_file_atomically(out("short.lab"), synth::write_lab(cut));
  r = run_command(fapcast("animate --wav " + take("wav") + " --align " + out("short.lab") + " --voice " + voice() +
                          " -o " + out("short.fap")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_EQ(static_cast<std::int64_t>(transport::read_track_file(out("short.fap")).frames.size()), frames_for(audio, 25));

  // Longer than the WAV by a second: refused.
  synth::LabFile longer = lab;
  const double end = longer.segments.back().end_s;
  longer.segments.push_back({end, end + 1.0, "sil"});
  longer.scores.push_back(std::nullopt);
  transport::write_file_atomically(out("long.lab"), synth::write_lab(longer));
  r = run_command(fapcast("animate --wav " + take("wav") + " --align " + out("long.lab") + " --voice " + voice() +
                          " -o " + out("long.fap")));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("alignment-longer-than-audio"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("long.fap")));
}

void BadInputExitsOneAndNamesIt() {
  auto expect_error = [](const std::string& args, const std::string& what) {
    const auto r = run_command(fapcast(args));
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << args << "\n" << r.err;
  };
  expect_error("say \"   \" --voice " + voice() + " -o " + out("e.fap"), "empty-text");
  expect_error("animate --wav " + out("none.wav") + " --align " + take("TextGrid") + " --voice " + voice() +
                   " -o " + out("e.fap"), "none.wav");
  expect_error("animate --wav " + take("wav") + " --align " + out("none.lab") + " --voice " + voice() +
                   " -o " + out("e.fap"), "none.lab");
  transport::write_file_atomically(out("bad.lab"), "0 1000000 sil\n1000000 2000000 xyz\n");
  expect_error("animate --wav " + take("wav") + " --align " + out("bad.lab") + " --voice " + voice() + " -o " +
                   out("e.fap"), "phone-label");
  transport::write_file_atomically(out("overlap.lab"), "0 2000000 sil\n1000000 3000000 aa\n");
  expect_error("animate --wav " + take("wav") + " --align " + out("overlap.lab") + " --voice " + voice() + " -o " +
                   out("e.fap"), "overlap.lab");
  transport::write_file_atomically(out("not-a-voice.fapv"), "this is not a voice\n");
  expect_error("say \"Hello.\" --voice " + out("not-a-voice.fapv") + " -o " + out("e.fap"), "not-a-voice.fapv");
  expect_error("say \"Hello.\" --voice " + out("missing.fapv") + " -o " + out("e.fap"), "missing.fapv");
  EXPECT_FALSE(fs::exists(out("e.fap")));
}

TEST_F(SayCli, SayAndAnimateEndToEnd) {
  {
    SCOPED_TRACE("SayWritesTheTrackInSyncWithTheWav");
    SayWritesTheTrackInSyncWithTheWav();
  }
  {
    SCOPED_TRACE("EveryFormatAndRate");
    EveryFormatAndRate();
  }
  {
    SCOPED_TRACE("AnimateFromTextGridAndLab");
    AnimateFromTextGridAndLab();
  }
  {
    SCOPED_TRACE("BadInputExitsOneAndNamesIt");
    BadInputExitsOneAndNamesIt();
  }
}

TEST(SayCliUsage, MistakesExitTwo) {
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.txt --voice v.fapv")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("say \"Hi.\"")).exit_code, 2);  // no -o
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.fap --fps 0")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("say \"Hi.\" -o x.fap --fps 500")).exit_code, 2);
  EXPECT_EQ(run_command(fapcast("animate --wav a.wav -o x.fap")).exit_code, 2);  // no --align
  EXPECT_EQ(run_command(fapcast("animate --wav a.wav --align a.txt -o x.fap")).exit_code, 2);
}

}  // namespace
}  // namespace fapcast::test
