#include "fapcast/talker/rest_padding.hpp"

#include <cmath>
#include <stdexcept>

namespace fapcast {

Speech with_rest(Speech speech, const RestPadding& padding) {
  if (!(padding.before_s >= 0) || !(padding.after_s >= 0))
    throw std::invalid_argument("rest padding: negative or not a number");
  const auto rate = static_cast<double>(speech.audio.sample_rate.hz);
  const auto before = static_cast<std::int64_t>(std::lround(padding.before_s * rate));
  const auto after = static_cast<std::int64_t>(std::lround(padding.after_s * rate));
  const std::int64_t length = speech.audio.instants() + before + after;
  const auto channels = static_cast<std::size_t>(speech.audio.channels);
  speech.audio.samples.insert(speech.audio.samples.begin(), static_cast<std::size_t>(before) * channels, 0);
  speech.audio.samples.insert(speech.audio.samples.end(), static_cast<std::size_t>(after) * channels, 0);
  for (TimedPhone& p : speech.phones) {
    p.start_sample += before;
    p.end_sample += before;
  }
  for (PhoneEvent& e : speech.events) {
    e.event_sample += before;
    e.release_sample += before;
  }
  for (TimedWord& w : speech.words) {
    w.start_sample += before;
    w.end_sample += before;
  }
  const bool events = speech.events.size() == speech.phones.size();  // one per phone, when given
  const auto rest_event = [](std::int64_t at) { return PhoneEvent{at, at, kNoWord, "_"}; };
  if (!speech.phones.empty() && speech.phones.front().phone == Phone::SIL) {
    speech.phones.front().start_sample = 0;
  } else if (before > 0) {
    const std::int64_t first = speech.phones.empty() ? before : speech.phones.front().start_sample;
    speech.phones.insert(speech.phones.begin(), TimedPhone{Phone::SIL, 0, first});
    if (events) speech.events.insert(speech.events.begin(), rest_event(0));
  }
  const std::int64_t speech_end = speech.phones.empty() ? before : speech.phones.back().end_sample;
  if (!speech.phones.empty() && speech.phones.back().phone == Phone::SIL) {
    speech.phones.back().end_sample = length;
  } else if (length > speech_end) {
    speech.phones.push_back(TimedPhone{Phone::SIL, speech_end, length});
    if (events) speech.events.push_back(rest_event(speech_end));
  }
  return speech;
}

}  // namespace fapcast
