#include "fapcast/synthesis/jaw_guide.hpp"

#include "fapcast/math/zero_phase_lowpass.hpp"

#include <algorithm>
#include <cmath>

namespace fapcast {

JawGuide make_jaw_guide(const Voice& voice) {
  const auto points = voice.feature_points();
  const auto chin = std::find_if(points.begin(), points.end(), [](const VoiceFeaturePoint& p) { return p.label == "2.1"; });
  if (chin == points.end())
    throw InputError(InputLocation{voice.file().source(), {}, {}}, "jaw-guide",
                     "the voice has no chin feature point (FP 2.1), which the jaw term measures");
  const Eigen::Index y = 3 * static_cast<Eigen::Index>(chin->vertex) + 1;
  const auto components = voice.pca_components();
  Eigen::VectorXf down(components.rows());  // chin travel downwards per unit of each coefficient, metres
  for (Eigen::Index c = 0; c < components.rows(); ++c) down[c] = -components(c, y);
  const auto frames = voice.frame_coefficients();
  const Eigen::VectorXf opening = frames * down;  // per frame, metres below the mean face

  const PhoneGraph& graph = voice.graph();
  const auto phones = voice.state_phones();
  JawGuide guide;
  guide.state_opening.resize(graph.size());
  std::array<double, kPhoneCount> sum{};
  std::array<std::size_t, kPhoneCount> count{};
  double speech_sum = 0.0, speech_square = 0.0;
  std::size_t speech = 0;
  for (StateId j = 0; j < graph.size(); ++j) {
    const FrameSpan span = graph.state(j).frames;
    const double mean = span.count == 0 ? 0.0 : opening.segment(span.first, span.count).cast<double>().mean();
    guide.state_opening[j] = static_cast<float>(mean);
    const auto p = static_cast<std::size_t>(phones[j]);
    sum[p] += mean, ++count[p];
    if (graph.state(j).viseme != VisemeClass::kSilence) speech_sum += mean, speech_square += mean * mean, ++speech;
  }
  const double centre = speech == 0 ? 0.0 : speech_sum / static_cast<double>(speech);
  const double spread = speech < 2 ? 0.0 : std::sqrt(std::max(0.0, speech_square / static_cast<double>(speech) - centre * centre));
  if (!(spread > 1e-6))  // a micrometre: a still chin gives the search nothing to follow
    throw InputError(InputLocation{voice.file().source(), {}, {}}, "jaw-guide",
                     "the chin (FP 2.1) does not move across the voice's phones: the jaw term has nothing to follow");
  for (float& v : guide.state_opening) v = static_cast<float>((v - centre) / spread);
  for (std::size_t p = 0; p < kPhoneCount; ++p)
    guide.phone_opening[p] = count[p] == 0 ? 0.0f : static_cast<float>((sum[p] / static_cast<double>(count[p]) - centre) / spread);
  guide.spread_mm = 1000.0 * spread;
  return guide;
}

namespace {

// Each target phone's mean opening on its frames, low-passed (frames from the first phone's first).
std::vector<double> wanted_per_frame(const JawGuide& guide, const TargetTimeline& timeline, double cutoff_hz) {
  const auto& targets = timeline.phones;
  if (targets.empty()) return {};
  const std::int64_t first = targets.front().first_frame;
  std::vector<double> laid(static_cast<std::size_t>(timeline.frame_count() - first));
  for (std::size_t t = 0; t < targets.size(); ++t)
    for (std::int64_t n = targets[t].first_frame; n < targets[t].end_frame; ++n)
      laid[static_cast<std::size_t>(n - first)] = guide.phone_opening[static_cast<std::size_t>(timeline.phone_of[t])];
  return laid.size() < 3 ? laid : zero_phase_lowpass(laid, static_cast<double>(kVoiceFramesPerSecond), cutoff_hz);
}

}  // namespace

std::vector<float> wanted_jaw(const JawGuide& guide, const TargetTimeline& timeline, double cutoff_hz) {
  const auto& targets = timeline.phones;
  if (targets.empty()) return {};
  const std::int64_t first = targets.front().first_frame;
  const std::vector<double> smooth = wanted_per_frame(guide, timeline, cutoff_hz);
  std::vector<float> out(targets.size());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    double s = 0.0;
    for (std::int64_t n = targets[t].first_frame; n < targets[t].end_frame; ++n) s += smooth[static_cast<std::size_t>(n - first)];
    out[t] = static_cast<float>(s / static_cast<double>(std::max<std::int64_t>(1, targets[t].end_frame - targets[t].first_frame)));
  }
  return out;
}

}  // namespace fapcast
