#include "fapcast/synthesis/synthesis.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/synthesis/tongue.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace fapcast {
namespace {

using V = VisemeClass;
// The nearest shapes first: same lip posture, then same jaw opening (spec/synthesis.md).
constexpr std::array<VisemeFallback, kVisemeClassCount> kFallbacks{{
    {V::kSilence, {V::kBilabial, V::kAlveolar, V::kNearCloseFront}},     // rest: lips together
    {V::kBilabial, {V::kSilence, V::kLabiodental, V::kAlveolar}},        // closed lips
    {V::kLabiodental, {V::kBilabial, V::kSibilant, V::kAlveolar}},       // lower lip up
    {V::kDental, {V::kAlveolar, V::kLateral, V::kSibilant}},             // jaw nearly closed
    {V::kAlveolar, {V::kSibilant, V::kLateral, V::kDental}},
    {V::kSibilant, {V::kAlveolar, V::kCloseFront, V::kDental}},          // teeth together, spread
    {V::kLateral, {V::kAlveolar, V::kDental, V::kNearCloseFront}},
    {V::kPostalveolar, {V::kRhotic, V::kLabialVelar, V::kSibilant}},     // protruded lips
    {V::kRhotic, {V::kPostalveolar, V::kNearCloseRounded, V::kLabialVelar}},
    {V::kBack, {V::kMidFront, V::kSchwa, V::kNearCloseFront}},           // jaw half open
    {V::kLabialVelar, {V::kCloseRounded, V::kNearCloseRounded, V::kRhotic}},
    {V::kCloseFront, {V::kNearCloseFront, V::kSibilant, V::kMidFront}},  // spread, near closed
    {V::kNearCloseFront, {V::kCloseFront, V::kMidFront, V::kBack}},
    {V::kMidFront, {V::kNearCloseFront, V::kOpenFront, V::kBack}},
    {V::kOpenFront, {V::kMidFront, V::kOpenUnrounded, V::kNearCloseFront}},
    {V::kOpenUnrounded, {V::kOpenFront, V::kMidFront, V::kOpenMidRounded}},  // jaw wide open
    {V::kOpenMidRounded, {V::kMidRounded, V::kOpenUnrounded, V::kNearCloseRounded}},
    {V::kMidRounded, {V::kOpenMidRounded, V::kNearCloseRounded, V::kCloseRounded}},
    {V::kNearCloseRounded, {V::kCloseRounded, V::kMidRounded, V::kRhotic}},
    {V::kCloseRounded, {V::kNearCloseRounded, V::kLabialVelar, V::kMidRounded}},
    {V::kSchwa, {V::kBack, V::kMidFront, V::kNearCloseFront}},           // neutral lips, jaw a little open
}};

constexpr bool fallbacks_in_order() {
  for (std::size_t i = 0; i < kVisemeClassCount; ++i)
    if (static_cast<std::size_t>(kFallbacks[i].viseme) != i) return false;
  return true;
}
static_assert(fallbacks_in_order(), "fallback rows must follow VisemeClass order");

}  // namespace

std::span<const VisemeFallback, kVisemeClassCount> viseme_fallbacks() { return kFallbacks; }

VisemeClass covered_viseme(const PhoneGraph& graph, VisemeClass v) {
  if (!graph.with_viseme(v).empty()) return v;
  const auto& row = kFallbacks[static_cast<std::size_t>(v)];
  for (VisemeClass s : row.substitutes)
    if (!graph.with_viseme(s).empty()) return s;
  std::string names;
  for (VisemeClass s : row.substitutes) names += (names.empty() ? "" : ", ") + std::string(viseme_class_name(s));
  throw InputError({"voice", {}, {}}, "viseme-not-covered",
                   "the voice has no phone of viseme class " + std::string(viseme_class_name(v)) +
                       " nor of its substitutes (" + names + ")");
}

std::optional<JawGuide> jaw_guide_for(const Voice& voice, const SynthesisOptions& options) {
  if (options.search.jaw_weight > 0.0) return make_jaw_guide(voice);
  const auto points = voice.feature_points();
  const bool chin = std::any_of(points.begin(), points.end(), [](const VoiceFeaturePoint& p) { return p.label == "2.1"; });
  if (!(options.jaw_level > 0.0) || !chin) return std::nullopt;
  return make_jaw_guide(voice);
}

SynthesizedTrack synthesize(const PhoneGraph& graph, const PcaFrames& frame_coefficients,
                            std::span<const TimedPhone> phones, SampleRate sample_rate,
                            std::int64_t end_sample, const SynthesisOptions& options,
                            const std::string& source, const JawGuide* jaw_guide) {
  return synthesize(graph, frame_coefficients, place_on_voice_grid(phones, sample_rate, end_sample, source), options,
                    jaw_guide);
}

SynthesizedTrack synthesize(const Voice& voice, std::span<const TimedPhone> phones, SampleRate sample_rate,
                            std::int64_t end_sample, const SynthesisOptions& options, const std::string& source) {
  const auto guide = jaw_guide_for(voice, options);
  return synthesize(voice.graph(), voice.frame_coefficients(), phones, sample_rate, end_sample, options, source,
                    guide ? &*guide : nullptr);
}

SynthesizedTrack synthesize(const PhoneGraph& graph, const PcaFrames& frame_coefficients,
                            TargetTimeline timeline, const SynthesisOptions& options, const JawGuide* jaw_guide) {
  SynthesizedTrack out;
  out.timeline = std::move(timeline);
  const auto& targets = out.timeline.phones;
  if (targets.empty()) {
    out.pca_frames.resize(0, frame_coefficients.cols());
    out.tongue.resize(0, static_cast<Eigen::Index>(kTongueFapCount));
    return out;
  }
  // The search and the concatenation see the covered classes; the timeline keeps what was asked for.
  std::vector<TargetPhone> covered(targets.begin(), targets.end());
  std::vector<VisemeClass> classes(covered.size());
  std::vector<std::int64_t> lengths(covered.size());
  for (std::size_t t = 0; t < covered.size(); ++t) {
    const VisemeClass c = covered_viseme(graph, covered[t].viseme);
    if (c != covered[t].viseme) ++out.substituted;
    covered[t].viseme = classes[t] = c;
    lengths[t] = covered[t].end_frame - covered[t].first_frame;
  }
  if (jaw_guide != nullptr && jaw_guide->state_opening.size() != graph.size())
    throw std::invalid_argument("synthesis: the jaw guide is another voice's (jaw_guide_for)");
  std::vector<float> jaw;
  if (options.search.jaw_weight > 0.0) {
    if (jaw_guide == nullptr) throw std::invalid_argument("synthesis: the jaw term needs the voice's jaw guide (jaw_guide_for)");
    jaw = wanted_jaw(*jaw_guide, out.timeline, options.jaw_cutoff_hz);
  }
  out.search = unit_search(graph, classes,
                           SearchTargets{lengths, jaw, jaw.empty() ? std::span<const float>{} : std::span<const float>(jaw_guide->state_opening)},
                           options.search);
  out.pca_frames = concatenate_units(graph, frame_coefficients, out.search, covered, options.concatenation);
  if (options.jaw_level > 0.0 && jaw_guide != nullptr && !jaw_guide->jaw_move.empty()) {
    level_jaw(*jaw_guide, out.timeline, out.pca_frames, options.jaw_cutoff_hz, options.jaw_level);
    out.jaw_levelled = true;
  }
  out.tongue = tongue_track(targets, out.timeline.phone_of);
  return out;
}

}  // namespace fapcast
