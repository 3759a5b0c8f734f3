// A stereo recording (praatIO's bobby_16bit_16khz_2ch.wav) is read as the mean of its two
// channels, checked against the file's own PCM bytes parsed here independently of libsndfile.
#include "fapcast/core/downmix.hpp"
#include "fapcast/core/wav_file.hpp"
#include "support/bad_inputs.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace fapcast {
namespace {

TEST(Downmix, StereoIsTheMeanOfItsChannels) {
  const auto path = std::filesystem::path(FAPCAST_TEST_DATA) / "speech/stereo/bobby_16bit_16khz_2ch.wav";
  const Audio stereo = read_wav(path);
  EXPECT_EQ(stereo.channels, 2);
  const Audio a = downmix_to_mono(stereo);
  EXPECT_EQ(a.channels, 1);
  EXPECT_EQ(a.sample_rate.hz, 16000);
  // RIFF: find the "data" chunk; 16-bit little-endian, L R interleaved.
  const std::string bytes = test::slurp(path);
  std::size_t pos = 12, data = 0, size = 0;
  while (pos + 8 <= bytes.size()) {
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + pos + 4, 4);
    if (bytes.compare(pos, 4, "data") == 0) {
      data = pos + 8;
      size = n;
      break;
    }
    pos += 8 + n + (n & 1);
  }
  ASSERT_GT(data, 0u);
  ASSERT_EQ(a.samples.size(), size / 4);
  std::size_t differing_channels = 0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    std::int16_t l = 0, r = 0;
    std::memcpy(&l, bytes.data() + data + 4 * i, 2);
    std::memcpy(&r, bytes.data() + data + 4 * i + 2, 2);
    const int sum = l + r;
    const int mean = (sum >= 0 ? sum + 1 : sum - 1) / 2;  // halves away from zero
    ASSERT_EQ(a.samples[i], mean) << "sample " << i;
    differing_channels += l != r;
  }
  EXPECT_GT(differing_channels, a.samples.size() / 10);  // a real stereo file, not a mono copy
}

TEST(Downmix, ThreeChannelsRoundHalvesAwayFromZero) {
  Audio a;
  a.sample_rate = SampleRate{8000};
  a.channels = 3;
  a.samples = {1, 0, 0, 2, 0, 0, -2, 0, 0, 32767, 32767, 32767, -32768, -32768, -32767};
  const Audio m = downmix_to_mono(a);
  EXPECT_EQ(m.sample_rate.hz, 8000);
  EXPECT_EQ(m.samples, (std::vector<std::int16_t>{0, 1, -1, 32767, -32768}));
  Audio mono = m;
  EXPECT_EQ(downmix_to_mono(mono).samples, m.samples);
  mono.channels = 0;
  EXPECT_THROW(downmix_to_mono(mono), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
