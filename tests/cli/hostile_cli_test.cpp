// Issue #17's bad inputs through the executable: each ended in exit 0 (or did its work first),
// and each now exits 1 with the file and the rule, or 2 for a usage mistake.
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace fapcast::test {
namespace {

const std::string kData = FAPCAST_TEST_DATA;
const std::string kJoy = kData + "/xface/joy.fap";

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A 16-bit mono PCM WAV of `frames` silent sampling instants at `rate`.
void write_silent_wav(const std::string& path, std::uint32_t rate, std::uint32_t frames) {
  std::ofstream out(path, std::ios::binary);
  const auto u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.put(static_cast<char>((v >> (8 * i)) & 0xff));
  };
  const auto u16 = [&](std::uint16_t v) {
    out.put(static_cast<char>(v & 0xff));
    out.put(static_cast<char>(v >> 8));
  };
  out.write("RIFF", 4);
  u32(36 + 2 * frames);
  out.write("WAVEfmt ", 8);
  u32(16);
  u16(1);  // PCM
  u16(1);  // mono
  u32(rate);
  u32(rate * 2);
  u16(2);
  u16(16);
  out.write("data", 4);
  u32(2 * frames);
  for (std::uint32_t i = 0; i < frames; ++i) u16(0);
}

// Attack 6: `recv -o /nonexistent/o.fap` listened for the whole session and failed at the end.
TEST(HostileCli, RecvChecksItsOutputBeforeListening) {
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_command(fapcast("recv udp://127.0.0.1:0 -o /nonexistent/dir/o.fap --timeout 5"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(has(r.err, "/nonexistent/dir/o.fap")) << r.err;
  EXPECT_FALSE(has(r.err, "listening")) << r.err;
  EXPECT_LT(seconds, 4.0) << "it waited for the --timeout before failing";
}

// Attack 8: `fap info` on a truncated .fba printed a summary with warnings and exited 0.
TEST(HostileCli, FapInfoRefusesATruncatedFba) {
  const std::string path = kData + "/fba/bad/bad.001.truncated.fba";
  const auto r = run_command(fapcast("fap info " + path));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_TRUE(has(r.err, path)) << r.err;
  EXPECT_TRUE(has(r.err, "frames lost")) << r.err;
}

// Attack 12: a corrupt .fba whose first start code is damaged was "not a text file".
TEST(HostileCli, FapInfoReportsACorruptFbaAsAnFba) {
  const std::string path = kData + "/fba/bad/bad.004.bad-start-code.fba";
  const auto r = run_command(fapcast("fap info " + path));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_TRUE(has(r.err, path)) << r.err;
  EXPECT_FALSE(has(r.err, "not a text file")) << r.err;
}

// Attack 8: output that never reached a full standard output was a success.
TEST(HostileCli, AFullStandardOutputIsAFailedRun) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  // The three commands of the issue; the voice is the tiny one of the voice fuzz seeds.
  const std::string lexicon = kData + "/lexicon/";
  for (const std::string& args :
       {"fap info " + kJoy, "voice info " + kData + "/../fuzz/corpus/voice_open_fuzz/tiny-with-fmap.fapv",
        "corpus script --cmudict " + lexicon + "mini-cmudict.out --word-counts " + lexicon +
            "mini-word-counts.tsv --common 2 --syllable-words 3"}) {
    // In a subshell: run_command's own redirection of standard output would otherwise win.
    const auto r = run_command("(" + fapcast(args) + " > /dev/full)");
    EXPECT_EQ(r.exit_code, 1) << args << ": " << r.err;
    EXPECT_TRUE(has(r.err, "standard output")) << args << ": " << r.err;
  }
}

// Attack 12: a URL that is not udp://HOST:PORT is a usage mistake (2), on both ends.
TEST(HostileCli, ABadUrlIsUsage) {
  const auto stream = run_command(fapcast("stream " + kJoy + " -o 127.0.0.1:9"));
  EXPECT_EQ(stream.exit_code, 2) << stream.err;
  EXPECT_TRUE(has(stream.err, "udp-url")) << stream.err;
  const auto recv = run_command(fapcast("recv 127.0.0.1:9 -o " + make_temp_dir("hostile_cli") + "/o.fap"));
  EXPECT_EQ(recv.exit_code, 2) << recv.err;
  EXPECT_TRUE(has(recv.err, "udp-url")) << recv.err;
}

// Attack 8: `stream --wav` with a cut-off WAV read it as a shorter one and exited 0.
TEST(HostileCli, StreamRefusesATruncatedWav) {
  const std::string dir = make_temp_dir("hostile_cli");
  const std::string wav = dir + "/cut.wav";
  write_silent_wav(wav, 48000, 48000 * 10);
  std::filesystem::resize_file(wav, 44 + 2 * 48000);  // the header still claims 10 s
  const auto r = run_command(fapcast("stream " + kJoy + " --wav " + wav + " -o udp://127.0.0.1:9 --no-pace"));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(has(r.err, wav)) << r.err;
  EXPECT_TRUE(has(r.err, "wav-truncated")) << r.err;
}

// Attack 8: audio far shorter than the animation was streamed as if it were its timeline.
TEST(HostileCli, StreamRefusesAudioShorterThanTheAnimation) {
  const std::string dir = make_temp_dir("hostile_cli");
  const std::string wav = dir + "/short.wav";
  write_silent_wav(wav, 48000, 4800);  // 0.1 s
  const auto r = run_command(fapcast("stream " + kJoy + " --wav " + wav + " -o udp://127.0.0.1:9 --no-pace"));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(has(r.err, "stream-audio-short")) << r.err;
}

// Attack 8: `corpus script` with an empty lexicon wrote 204 nonsense items and exited 0.
TEST(HostileCli, CorpusScriptRefusesAnEmptyLexicon) {
  const std::string dir = make_temp_dir("hostile_cli");
  std::ofstream(dir + "/empty.out").flush();
  const auto r = run_command(fapcast("corpus script --cmudict " + dir + "/empty.out --word-counts " + kData +
                                     "/lexicon/mini-word-counts.tsv -o " + dir + "/script.tsv"));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_TRUE(has(r.err, "lexicon-empty")) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/script.tsv"));
}


// Attack 7: `render` took a .glb whose key times imply 1.31 MHz (the glb fuzz input) with exit 0.
TEST(HostileCli, RenderRefusesTheFuzzersGlb) {
  const std::string glb = kData + "/gltf/fuzz-regressions/glb.001.gltf-frame-rate.glb";
  const std::string out = make_temp_dir("hostile_cli") + "/frames";
  const auto r = run_command(fapcast("render " + glb + " -o " + out));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(has(r.err, glb)) << r.err;
  EXPECT_TRUE(has(r.err, "gltf-frame-rate")) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// Attack 6 for every command that writes a file: each did all its work (read, coded, built a
// voice, synthesized speech) before it learnt that its output could not be written. Each now
// fails first, naming the output; its inputs do not exist, so an error about them would show
// that the command began its work first.
struct UnwritableOutput {
  const char* family;
  std::string args;    // the command line after `fapcast`
  std::string output;  // the path the message must name
};

std::string unwritable_name(const testing::TestParamInfo<UnwritableOutput>& info) { return info.param.family; }

class HostileOutput : public testing::TestWithParam<UnwritableOutput> {};

TEST_P(HostileOutput, AnUnwritableOutputFailsBeforeTheWork) {
  const auto& p = GetParam();
  const auto r = run_command(fapcast(p.args));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_TRUE(has(r.err, p.output)) << r.err;
  EXPECT_FALSE(has(r.err, "/nonexistent/in")) << "it read its input first: " << r.err;
}

const std::string kNo = "/nonexistent/dir/";
const std::string kIn = "/nonexistent/in";
INSTANTIATE_TEST_SUITE_P(
    HostileCli, HostileOutput,
    testing::Values(
        UnwritableOutput{"encode", "encode " + kIn + ".fap -o " + kNo + "x.fba", kNo + "x.fba"},
        UnwritableOutput{"decode", "decode " + kIn + ".fba -o " + kNo + "x.fap", kNo + "x.fap"},
        UnwritableOutput{"export", "export " + kIn + ".fap -o " + kNo + "x.bvh", kNo + "x.bvh"},
        UnwritableOutput{"fap_convert", "fap convert " + kIn + ".fap -o " + kNo + "x.fap", kNo + "x.fap"},
        UnwritableOutput{"voice_build", "voice build " + kIn + " -o " + kNo + "x.fapv", kNo + "x.fapv"},
        UnwritableOutput{"voice_adapt",
                         "voice adapt " + kIn + ".fapv " + kIn + "g.obj " + kIn + "s.obj -o " + kNo + "x.fapv",
                         kNo + "x.fapv"},
        UnwritableOutput{"corpus_script",
                         "corpus script --cmudict " + kIn + ".out --word-counts " + kIn + ".tsv -o " + kNo + "x.tsv",
                         kNo + "x.tsv"},
        UnwritableOutput{"say", "say hello --voice " + kIn + ".fapv -o " + kNo + "x.fap", kNo + "x.fap"},
        UnwritableOutput{"say_wav",
                         "say hello --voice " + kIn + ".fapv -o " + testing::TempDir() + "hostile_say.glb --wav-out " +
                             kNo + "x.wav",
                         kNo + "x.wav"},
        UnwritableOutput{"animate", "animate " + kIn + ".wav " + kIn + ".lab -o " + kNo + "x.glb", kNo + "x.glb"},
        UnwritableOutput{"rig", "animate " + kIn + ".wav " + kIn + ".lab --rig arkit -o " + kNo + "x.csv",
                         kNo + "x.csv"},
        UnwritableOutput{"expressions", "expressions -o " + kNo + "x.glb", kNo + "x.glb"},
        UnwritableOutput{"eval_articulography_json",
                         "eval articulography " + kIn + ".ema " + kIn + ".wav " + kIn + ".lab --json-out " + kNo + "x.json",
                         kNo + "x.json"},
        UnwritableOutput{"eval_articulography_svg",
                         "eval articulography " + kIn + ".ema " + kIn + ".wav --text hi --svg-out " + kNo + "x.svg",
                         kNo + "x.svg"}),
    unwritable_name);

}  // namespace
}  // namespace fapcast::test
