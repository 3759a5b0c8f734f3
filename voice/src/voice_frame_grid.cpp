#include "fapcast/voice/voice_frame_grid.hpp"

#include "fapcast/core/input_error.hpp"

#include <stdexcept>
#include <string>

namespace fapcast {
namespace {
std::string describe(std::span<const TimedPhone> phones, std::size_t i, std::size_t first_phone) {
  return "phone " + std::to_string(first_phone + i) + " '" + std::string(arpabet(phones[i].phone)) + "' [" +
         std::to_string(phones[i].start_sample) + ", " + std::to_string(phones[i].end_sample) + ")";
}

void append(TargetTimeline& out, Phone phone, std::int64_t first, std::int64_t end) {
  if (end <= first) return;
  const VisemeClass v = search_viseme(phone);
  out.phones.push_back({v, first, end, is_held(v)});
  out.phone_of.push_back(phone);
}

}  // namespace

TargetTimeline place_on_voice_grid(std::span<const TimedPhone> phones, SampleRate sample_rate,
                                   std::int64_t end_sample, const std::string& source, std::size_t first_phone) {
  if (!sample_rate.valid())
    throw std::invalid_argument("voice grid: sample rate " + std::to_string(sample_rate.hz) + " Hz");
  TargetTimeline out;
  out.sample_rate = sample_rate;
  std::int64_t previous_end = 0;
  std::int64_t frame = 0;  // where the next target starts
  auto fill_silence_to = [&](std::int64_t sample) {
    const std::int64_t to = first_frame_at(sample, kVoiceFrameRate, sample_rate);
    if (to > frame) {
      append(out, Phone::SIL, frame, to);
      ++out.gaps_filled;
      frame = to;
    }
  };
  for (std::size_t i = 0; i < phones.size(); ++i) {
    const TimedPhone& p = phones[i];
    if (p.start_sample < 0)
      throw InputError({source, {}, {}}, "phone-negative-start", describe(phones, i, first_phone) + " starts before sample 0");
    if (p.end_sample < p.start_sample)
      throw InputError({source, {}, {}}, "phone-reversed", describe(phones, i, first_phone) + " ends before it starts");
    if (p.start_sample < previous_end)
      throw InputError({source, {}, {}}, "phone-overlap",
                       describe(phones, i, first_phone) + " starts before the previous phone ends (sample " +
                           std::to_string(previous_end) + "): phones must be in time order");
    fill_silence_to(p.start_sample);
    const std::int64_t end = first_frame_at(p.end_sample, kVoiceFrameRate, sample_rate);
    if (end <= frame) {
      ++out.dropped;  // zero duration, or between two frame instants
    } else {
      // Two silences in a row (a gap next to a SIL phone) stay two targets: harmless.
      append(out, p.phone, frame, end);
      frame = end;
    }
    previous_end = p.end_sample;
  }
  if (end_sample > previous_end) fill_silence_to(end_sample);
  return out;
}

}  // namespace fapcast
