#include "fapcast/core/wav_file.hpp"

#include "fapcast/core/file_io.hpp"
#include "support/run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>

namespace fapcast {
namespace {

namespace fs = std::filesystem;
const fs::path kData = fs::path(FAPCAST_TEST_DATA) / "transport";

// A minimal canonical PCM WAV, written byte by byte (independent of libsndfile and SoX).
std::string canonical_wav(int rate, int channels, const std::vector<std::int16_t>& samples) {
  std::string out;
  const auto u32 = [&](std::uint32_t v) { for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>(v >> (8 * i))); };
  const auto u16 = [&](std::uint16_t v) { out.push_back(static_cast<char>(v)); out.push_back(static_cast<char>(v >> 8)); };
  const auto data_bytes = static_cast<std::uint32_t>(2 * samples.size());
  out += "RIFF"; u32(36 + data_bytes); out += "WAVEfmt "; u32(16); u16(1); u16(static_cast<std::uint16_t>(channels));
  u32(static_cast<std::uint32_t>(rate)); u32(static_cast<std::uint32_t>(rate * channels * 2));
  u16(static_cast<std::uint16_t>(channels * 2)); u16(16); out += "data"; u32(data_bytes);
  for (const auto s : samples) u16(static_cast<std::uint16_t>(s));
  return out;
}

TEST(WavFile, ReadsEveryInterleavedSampleExactly) {
  const std::string dir = test::make_temp_dir("wav");
  const std::vector<std::int16_t> samples{0, 1, -1, 32767, -32768, 100, -100, 7, 8};
  write_file_atomically(dir + "/three_ch.wav", canonical_wav(22050, 3, samples));
  const Audio audio = read_wav(dir + "/three_ch.wav");
  EXPECT_EQ(audio.sample_rate.hz, 22050);
  EXPECT_EQ(audio.channels, 3);
  EXPECT_EQ(audio.instants(), 3);
  EXPECT_EQ(audio.samples, samples);
}

// A WAV written piece by piece through an AtomicFile (the header's lengths patched at the end)
// is byte for byte wav_bytes() of the whole, and nothing appears before commit.
TEST(WavFile, WriterInPiecesEqualsTheWholeAndCommitsAtomically) {
  const std::string dir = test::make_temp_dir("wav_writer");
  Audio whole;
  whole.sample_rate = SampleRate{22050};
  for (int i = 0; i < 50'000; ++i) whole.samples.push_back(static_cast<std::int16_t>((i * 7919) % 65536 - 32768));
  const fs::path path = dir + "/pieces.wav";
  {
    AtomicFile file(path);
    WavWriter writer(file, whole.sample_rate);
    const std::span<const std::int16_t> all(whole.samples);
    writer.append(all.first(1));
    writer.append(all.subspan(1, 20'000));
    writer.append(all.subspan(20'001, 0));
    writer.append(all.subspan(20'001));
    EXPECT_EQ(writer.instants(), 50'000);
    writer.finish();
    EXPECT_THROW(writer.append(all.first(1)), std::logic_error);
    EXPECT_FALSE(fs::exists(path));
    file.commit();
  }
  EXPECT_EQ(read_file(path), wav_bytes(whole));
  const Audio back = read_mono_wav(path);
  EXPECT_EQ(back.samples, whole.samples);
  {
    AtomicFile file(dir + "/empty.wav");
    WavWriter writer(file, whole.sample_rate);
    writer.finish();
    file.commit();
  }
  Audio silence;
  silence.sample_rate = whole.sample_rate;
  EXPECT_EQ(read_file(dir + "/empty.wav"), wav_bytes(silence));
  AtomicFile bad(dir + "/bad.wav");
  EXPECT_THROW(WavWriter(bad, SampleRate{0}), std::invalid_argument);
}

TEST(WavFile, ReadsTheSoxFixture) {
  const Audio audio = read_wav(kData / "tone_16k_mono.wav");
  EXPECT_EQ(audio.sample_rate.hz, 16000);
  EXPECT_EQ(audio.channels, 1);
  EXPECT_EQ(audio.instants(), 800);
}

struct SoxCase {
  const char* name;
  const char* args;  // sox output options
  int rate;
  int channels;
};
class WavFromSox : public testing::TestWithParam<SoxCase> {};

// Files written by another program in formats libsndfile reads: rate, channels and length agree.
TEST_P(WavFromSox, RateChannelsAndLength) {
  const SoxCase& c = GetParam();
  const std::string dir = test::make_temp_dir("sox");
  const std::string file = dir + "/" + c.name;
  const auto r = test::run_command("sox -n " + std::string(c.args) + " " + file + " synth 0.1 sine 300");
  if (r.exit_code != 0) GTEST_SKIP() << "sox failed: " << r.err;
  const Audio audio = read_wav(file);
  EXPECT_EQ(audio.sample_rate.hz, c.rate);
  EXPECT_EQ(audio.channels, c.channels);
  EXPECT_EQ(audio.instants(), c.rate / 10);
}
INSTANTIATE_TEST_SUITE_P(Table, WavFromSox,
                         testing::Values(SoxCase{"s16_48k_stereo.wav", "-r 48000 -c 2 -b 16", 48000, 2},
                                         SoxCase{"s24_44k_mono.wav", "-r 44100 -c 1 -b 24", 44100, 1},
                                         SoxCase{"f32_96k_6ch.wav", "-r 96000 -c 6 -e floating-point -b 32", 96000, 6},
                                         SoxCase{"u8_8k_mono.wav", "-r 8000 -c 1 -b 8", 8000, 1},
                                         SoxCase{"flac_32k.flac", "-r 32000 -c 2", 32000, 2}),
                         [](const auto& info) { return std::to_string(info.index); });

TEST(WavFile, BadFilesMatchTheGoldenList) {
  std::ifstream golden(kData / "bad" / "expected-errors.txt");
  std::string line;
  int checked = 0;
  while (std::getline(golden, line)) {
    const auto colon = line.find(": ");
    const std::string name = line.substr(0, colon);
    const std::string rule = line.substr(colon + 2);
    try {
      read_wav(kData / "bad" / name);
      ADD_FAILURE() << name << " was accepted";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(name), std::string::npos) << what;
      EXPECT_NE(what.find(rule), std::string::npos) << what;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(WavFile, MissingFileAndLengthLimitNameTheFile) {
  EXPECT_THROW(read_wav("/nonexistent/x.wav"), std::runtime_error);
  try {
    read_wav(kData / "tone_16k_mono.wav", 0);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("tone_16k_mono.wav: wav-too-long"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fapcast
