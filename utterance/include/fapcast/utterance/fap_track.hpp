#pragma once
// A synthesised track (60 fps PCA frames + tongue) as FAP frames through the codec, at the
// requested frame rate on the WAV timeline: what `say`, `animate` and `serve` send or write.
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/codec/feature_point_basis.hpp"
#include "fapcast/synthesis/speech_expression.hpp"
#include "fapcast/synthesis/synthesis.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace fapcast {

struct AnimationOptions {
  FrameRate rate{25, 1};  // output frames per second
  bool viseme = false;           // also write FAP 1 (the MPEG-4 viseme of the phone on screen)
  std::string name = "fapcast";  // the track's name (.fap header)
  std::optional<ExpressionField> expression;  // FAP 2 in every frame, when set
};

// FAP 2 for a blend: select / intensity pairs, no init_face, no expression_def.
ExpressionField expression_field(const ExpressionBlend& blend);

// The frames at `rate` shown while audio of `end_sample` samples plays: every j with
// frame_to_sample(j, rate, sample_rate) < end_sample.
std::int64_t frames_shown(std::int64_t end_sample, FrameRate rate, SampleRate sample_rate);

// The FAP frames of `track` at the voice's 60 fps, one per row of track.pca_frames (the masks
// and values fap_track resamples; options.rate is not used).
FapSequence voice_rate_faps(const SynthesizedTrack& track, const FeaturePointBasis& basis,
                            const AnimationOptions& options);

// FAP frames of `track` at options.rate: frame j shows the 60 fps frames interpolated at
// j / rate seconds (resample_track, linear), i.e. sample
// frame_to_sample(j, rate, sample_rate) of the WAV; exactly the frames shown before
// `end_sample` (the audio's length) are kept. Masks: drivable_faps(basis) plus the tongue (43-47)
// and, optionally, FAP 1 and FAP 2. track.pca_frames hold one weight per basis component
// (speech_weights: with an expression, its weight is the last column).
FapSequence fap_track(const SynthesizedTrack& track, const FeaturePointBasis& basis,
                      const AnimationOptions& options, std::int64_t end_sample);

}  // namespace fapcast
