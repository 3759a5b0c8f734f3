// The one frame <-> sample rule: first_frame_at is the smallest frame frame_to_sample puts at or
// after a sample, and sample_to_frame the last one at or before it, at audio rates from 7 Hz
// to 48 kHz and frame rates from 25/1 to 30000/1001.
#include "fapcast/core/frame_rate.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

TEST(FrameRate, FirstFrameAtAndSampleToFrameInvertFrameToSample) {
  for (const FrameRate rate : {FrameRate{60, 1}, FrameRate{25, 1}, FrameRate{30000, 1001}, FrameRate{120, 1}}) {
    for (const std::int64_t sample_rate : {8000, 16000, 22050, 44100, 48000, 11025, 7}) {
      for (std::int64_t s = 0; s < 5000; ++s) {
        const std::int64_t n = first_frame_at(s, rate, SampleRate{sample_rate});
        ASSERT_GE(frame_to_sample(n, rate, SampleRate{sample_rate}), s) << s << " @ " << sample_rate << " " << rate;
        if (n > 0) {
          ASSERT_LT(frame_to_sample(n - 1, rate, SampleRate{sample_rate}), s) << s << " @ " << sample_rate << " " << rate;
        }
        const std::int64_t k = sample_to_frame(s, rate, SampleRate{sample_rate});
        ASSERT_LE(frame_to_sample(k, rate, SampleRate{sample_rate}), s) << s << " @ " << sample_rate << " " << rate;
        ASSERT_GT(frame_to_sample(k + 1, rate, SampleRate{sample_rate}), s) << s << " @ " << sample_rate << " " << rate;
      }
    }
  }
}

}  // namespace
}  // namespace fapcast
