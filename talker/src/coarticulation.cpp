#include "fapcast/talker/coarticulation.hpp"

#include "fapcast/math/dominance.hpp"

#include <algorithm>
#include <stdexcept>

namespace fapcast {
namespace {

// Effort scales only the channels whose extent varies with effort; contacts (closure, lip to
// teeth, tongue contacts) must be met whatever the effort.
constexpr std::array<bool, kChannelCount> kEffortScaled{true, true, true, true,
                                                        false, false, false, false};

// A phone's articulation and centre, looked up once per timeline rather than once per frame.
struct PlacedPhone {
  const PhoneArticulation* articulation;
  double centre_s;
};

std::vector<PlacedPhone> place(const PhoneTimeline& timeline) {
  std::vector<PlacedPhone> placed;
  placed.reserve(timeline.phones.size());
  for (const auto& p : timeline.phones)
    placed.push_back({&phone_articulation(p.phone),
                      0.5 * static_cast<double>(p.start_sample + p.end_sample) / static_cast<double>(timeline.sample_rate.hz)});
  return placed;
}

std::array<float, kChannelCount> values_at(const std::vector<PlacedPhone>& phones, double t_s,
                                           float effort, DominanceBlend& blend) {
  blend.clear();
  for (const auto& p : phones) {
    const double tau = t_s - p.centre_s;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      float target = p.articulation->target[c];
      if (kEffortScaled[c]) target = std::clamp(target * effort, 0.0f, 1.0f);
      blend.add(c, p.articulation->dominance[c].at(tau), target);
    }
  }
  std::array<float, kChannelCount> out{};
  for (std::size_t c = 0; c < kChannelCount; ++c) out[c] = static_cast<float>(blend.value(c));
  return out;
}

}  // namespace

std::array<float, kChannelCount> ChannelTracks::frame(Eigen::Index k) const {
  std::array<float, kChannelCount> out{};
  for (std::size_t c = 0; c < kChannelCount; ++c) out[c] = values(static_cast<Eigen::Index>(c), k);
  return out;
}

void validate_timeline(const PhoneTimeline& timeline) {
  if (!timeline.sample_rate.valid())
    throw std::invalid_argument("phone timeline: sample rate " +
                                std::to_string(timeline.sample_rate.hz) + " Hz is not positive");
  std::int64_t previous_end = 0;
  for (std::size_t i = 0; i < timeline.phones.size(); ++i) {
    const auto& p = timeline.phones[i];
    const auto where = "phone timeline: phone " + std::to_string(i) + " '" + std::string(arpabet(p.phone)) + "': ";
    if (p.start_sample < previous_end)
      throw std::invalid_argument(where + "starts at sample " + std::to_string(p.start_sample) +
                                  " before the previous phone ends (" +
                                  std::to_string(previous_end) + ")");
    if (p.end_sample <= p.start_sample)
      throw std::invalid_argument(where + "empty or reversed span");
    previous_end = p.end_sample;
  }
}

std::array<float, kChannelCount> channel_values_at(const PhoneTimeline& timeline, double t_s,
                                                   float effort) {
  validate_timeline(timeline);
  DominanceBlend blend(kChannelCount);
  return values_at(place(timeline), t_s, effort, blend);
}

ChannelTracks coarticulate(const PhoneTimeline& timeline, const CoarticulationOptions& options) {
  validate_timeline(timeline);
  if (options.frame_rate_hz <= 0)
    throw std::invalid_argument("coarticulate: frame rate must be positive");
  if (!(options.effort > 0.0f))
    throw std::invalid_argument("coarticulate: effort must be positive");
  ChannelTracks tracks;
  tracks.frame_rate_hz = options.frame_rate_hz;
  const std::int64_t end = timeline.phones.empty() ? 0 : timeline.phones.back().end_sample;
  const std::int64_t frames =
      (end * options.frame_rate_hz + timeline.sample_rate.hz - 1) / timeline.sample_rate.hz;
  tracks.values.resize(static_cast<int>(kChannelCount), frames);
  const auto phones = place(timeline);
  DominanceBlend blend(kChannelCount);
  for (std::int64_t k = 0; k < frames; ++k) {
    const auto v = values_at(phones, static_cast<double>(k) / options.frame_rate_hz, options.effort, blend);
    for (std::size_t c = 0; c < kChannelCount; ++c)
      tracks.values(static_cast<Eigen::Index>(c), k) = std::clamp(v[c], 0.0f, 1.0f);
  }
  return tracks;
}

Eigen::MatrixXf expression_weights(const ChannelTracks& tracks, const ShapeMapper& mapper) {
  Eigen::MatrixXf weights(static_cast<Eigen::Index>(mapper.shape_count()), tracks.frame_count());
  for (Eigen::Index k = 0; k < tracks.frame_count(); ++k) {
    const auto w = mapper(tracks.frame(k));
    weights.col(k) = Eigen::Map<const Eigen::VectorXf>(w.data(), static_cast<Eigen::Index>(w.size()));
  }
  return weights;
}

}  // namespace fapcast
