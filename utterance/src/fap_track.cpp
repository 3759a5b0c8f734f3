#include "fapcast/utterance/fap_track.hpp"

#include "fapcast/codec/pca_faps.hpp"
#include "fapcast/synthesis/tongue.hpp"
#include "fapcast/transport/track_resample.hpp"

#include <cmath>
#include <utility>

namespace fapcast {

FapSequence voice_rate_faps(const SynthesizedTrack& track, const FeaturePointBasis& basis,
                            const AnimationOptions& options) {
  FapSequence voice_rate{options.name, {static_cast<std::uint32_t>(kVoiceFramesPerSecond), 1},
                                pca_to_faps(track.pca_frames, basis)};
  const auto& targets = track.timeline.phones;
  std::size_t t = 0;
  for (std::size_t n = 0; n < voice_rate.frames.size(); ++n) {
    FapFrame& f = voice_rate.frames[n];
    if (options.expression) {
      f.mask.set(kExpressionFap);
      f.expression = *options.expression;
    }
    for (std::size_t i = 0; i < kTongueFapCount; ++i)
      f.set(kFirstTongueFap + static_cast<int>(i),
            static_cast<std::int32_t>(std::lround(track.tongue(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(i)))));
    if (options.viseme) {
      while (static_cast<std::int64_t>(n) >= targets[t].end_frame) ++t;
      f.mask.set(kVisemeFap);
      f.viseme = {static_cast<std::uint8_t>(mpeg4_viseme(track.timeline.phone_of[t])), 0, 63, false};
    }
  }
  return voice_rate;
}

FapSequence fap_track(const SynthesizedTrack& track, const FeaturePointBasis& basis,
                      const AnimationOptions& options, std::int64_t end_sample) {
  FapSequence voice_rate = voice_rate_faps(track, basis, options);
  FapSequence out = voice_rate.rate == options.rate
                               ? std::move(voice_rate)
                               : resample_track(voice_rate, options.rate, ResampleMode::kLinear);
  // The 60 fps grid ends on the first instant at or after the audio's end; at another rate that
  // can leave one frame shown after the sound has ended.
  const auto shown = static_cast<std::size_t>(frames_shown(end_sample, options.rate, track.timeline.sample_rate));
  if (out.frames.size() > shown) out.frames.resize(shown);
  return out;
}

std::int64_t frames_shown(std::int64_t end_sample, FrameRate rate, SampleRate sample_rate) {
  return end_sample > 0 ? sample_to_frame(end_sample - 1, rate, sample_rate) + 1 : 0;
}

ExpressionField expression_field(const ExpressionBlend& blend) {
  ExpressionField f;
  f.select1 = static_cast<std::uint8_t>(blend.first.expression);
  f.intensity1 = static_cast<std::uint8_t>(blend.first.intensity);
  if (blend.second) {
    f.select2 = static_cast<std::uint8_t>(blend.second->expression);
    f.intensity2 = static_cast<std::uint8_t>(blend.second->intensity);
  }
  return f;
}

}  // namespace fapcast
