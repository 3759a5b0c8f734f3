#include "fapcast/recognise/resample.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace fapcast {
namespace {

Audio sine(SampleRate rate, double hz, double seconds, int channels = 1) {
  Audio a{rate, channels, {}};
  const auto n = static_cast<std::int64_t>(seconds * static_cast<double>(rate.hz));
  for (std::int64_t i = 0; i < n; ++i)
    for (int c = 0; c < channels; ++c)
      a.samples.push_back(static_cast<std::int16_t>(
          std::lround(10000 * std::sin(2 * std::numbers::pi * hz * static_cast<double>(i) / static_cast<double>(rate.hz)))));
  return a;
}

// Correlation of `a` with a sine of `hz` at its rate, over its middle half: 1 for that sine.
double match(const Audio& a, double hz) {
  double re = 0, im = 0, energy = 0;
  const std::size_t n = a.samples.size();
  for (std::size_t i = n / 4; i < 3 * n / 4; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(a.sample_rate.hz);
    re += a.samples[i] * std::cos(2 * std::numbers::pi * hz * t);
    im += a.samples[i] * std::sin(2 * std::numbers::pi * hz * t);
    energy += static_cast<double>(a.samples[i]) * a.samples[i];
  }
  return std::sqrt(re * re + im * im) / std::sqrt(energy * static_cast<double>(n / 2) / 2);
}

TEST(Resample, A20kHzToneIsTheSameToneAt16kHz) {
  const Audio in = sine(SampleRate{20000}, 440, 1.0);
  const Audio out = resample_mono(in, SampleRate{16000});
  EXPECT_EQ(out.sample_rate, SampleRate{16000});
  EXPECT_EQ(out.channels, 1);
  EXPECT_NEAR(static_cast<double>(out.samples.size()), 16000, 2);
  EXPECT_GT(match(out, 440), 0.99);
  EXPECT_LT(match(out, 550), 0.05);
}

TEST(Resample, StereoIsMixedDownFirst) {
  Audio in = sine(SampleRate{16000}, 300, 0.5, 2);
  for (std::size_t i = 1; i < in.samples.size(); i += 2) in.samples[i] = 0;  // right channel silent
  const Audio out = resample_mono(in, SampleRate{16000});
  ASSERT_EQ(out.samples.size(), in.samples.size() / 2);
  EXPECT_EQ(out.samples[100], static_cast<std::int16_t>(std::lround(in.samples[200] / 2.0)));
}

TEST(Resample, MonoAtTheRateComesBackAsItIs) {
  const Audio in = sine(SampleRate{16000}, 300, 0.1);
  EXPECT_EQ(resample_mono(in, SampleRate{16000}).samples, in.samples);
}

TEST(Resample, RatesOutOfRangeAreRefused) {
  EXPECT_THROW((void)resample_mono(sine(SampleRate{4000}, 300, 0.1), SampleRate{16000}), std::invalid_argument);
  EXPECT_THROW((void)resample_mono(sine(SampleRate{16000}, 300, 0.1), SampleRate{400000}), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
