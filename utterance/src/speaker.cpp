#include "fapcast/utterance/speaker.hpp"

#include "fapcast/utterance/fap_track.hpp"
#include "fapcast/utterance/voice_face.hpp"
#include "fapcast/voice/voice_frame_grid.hpp"

#include <algorithm>

namespace fapcast {
namespace {
using Clock = std::chrono::steady_clock;
}

Speaker::Speaker(const Voice& voice, SpeakerSettings settings, const std::string& source)
    : voice_(voice), jaw_guide_(jaw_guide_for(voice, settings.synthesis)), settings_(std::move(settings)), source_(source) {
  check_voice_phone_set(voice_, source_);
  basis_ = speech_basis(voice_, settings_.expression);
  face_ = face_basis(basis_, voice_, source_);
}

SpokenSentence Speaker::speak(std::string_view text) const {
  SpokenSentence out;
  const Clock::time_point t0 = Clock::now();
  Speech speech = fapcast::speak(text, settings_.speech);
  const Clock::time_point t1 = Clock::now();
  out.speech_time = t1 - t0;
  out.audio = std::move(speech.audio);
  out.phones = std::move(speech.phones);
  if (out.phones.empty()) return out;
  const auto samples = static_cast<std::int64_t>(out.audio.samples.size());
  SynthesizedTrack track = synthesize(voice_.graph(), voice_.frame_coefficients(), out.phones,
                                      out.audio.sample_rate, samples, settings_.synthesis, source_,
                                      jaw_guide_ ? &*jaw_guide_ : nullptr);
  AnimationOptions animation;
  animation.rate = settings_.rate;
  animation.viseme = settings_.viseme;
  animation.name = settings_.name;
  if (settings_.expression) animation.expression = expression_field(*settings_.expression);
  const Eigen::MatrixXf pca = track.pca_frames;
  track.pca_frames = speech_weights(track.pca_frames, basis_);
  out.faps = fap_track(track, face_, animation, samples);
  out.weights = resample_rows(pca, kVoiceFrameRate, settings_.rate, static_cast<std::int64_t>(out.faps.frames.size()));
  out.animation_time = Clock::now() - t1;
  return out;
}

Eigen::MatrixXf resample_rows(const Eigen::MatrixXf& frames, FrameRate from, FrameRate to, std::int64_t count) {
  Eigen::MatrixXf out(count, frames.cols());
  if (frames.rows() == 0) {
    out.setZero();
    return out;
  }
  // Row j sits at j * (from.num * to.den) / (to.num * from.den) rows of the input.
  const auto num = static_cast<std::int64_t>(from.numerator) * to.denominator;
  const auto den = static_cast<std::int64_t>(to.numerator) * from.denominator;
  const Eigen::Index last = frames.rows() - 1;
  for (std::int64_t j = 0; j < count; ++j) {
    const std::int64_t at = j * num;
    const auto row = static_cast<Eigen::Index>(at / den);
    const float fraction = static_cast<float>(at % den) / static_cast<float>(den);
    if (row >= last)
      out.row(j) = frames.row(last);
    else
      out.row(j) = (1.0f - fraction) * frames.row(row) + fraction * frames.row(row + 1);
  }
  return out;
}

}  // namespace fapcast
