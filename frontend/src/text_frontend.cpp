#include "fapcast/frontend/text_frontend.hpp"

#include <espeak-ng/speak_lib.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "fapcast/core/input_error.hpp"
#include "fapcast/phonetics/phone_map.hpp"

namespace fapcast {

namespace {

// What the synthesis callback collects for one espeak_Synth call.
struct RawEvent {
  espeak_EVENT_TYPE type;
  std::int64_t sample;
  int text_position;  // 1-based character index (POS_CHARACTER)
  int length;         // characters, for word events
  std::string name;   // phoneme mnemonic, for phoneme events
};

struct Collector {
  std::vector<std::int16_t> samples;
  std::vector<RawEvent> events;
};

std::mutex& espeak_mutex() {
  static std::mutex m;
  return m;
}

Collector* g_collector = nullptr;  // guarded by espeak_mutex()
int g_sample_rate_hz = 0;          // guarded by espeak_mutex(); 0 until initialised

int collect(short* wav, int count, espeak_EVENT* events) {
  if (g_collector == nullptr) return 0;
  if (wav != nullptr && count > 0) g_collector->samples.insert(g_collector->samples.end(), wav, wav + count);
  for (const espeak_EVENT* e = events; e != nullptr && e->type != espeakEVENT_LIST_TERMINATED; ++e) {
    if (e->type != espeakEVENT_PHONEME && e->type != espeakEVENT_WORD) continue;
    RawEvent raw{e->type, e->sample, e->text_position, e->length, {}};
    if (e->type == espeakEVENT_PHONEME) raw.name.assign(e->id.string, strnlen(e->id.string, sizeof e->id.string));
    g_collector->events.push_back(std::move(raw));
  }
  return 0;  // continue
}

// Initialises espeak-ng once (caller holds the mutex) and returns its sample rate.
int ensure_espeak() {
  if (g_sample_rate_hz > 0) return g_sample_rate_hz;
  const int rate = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr,
                                     espeakINITIALIZE_PHONEME_EVENTS | espeakINITIALIZE_DONT_EXIT);
  if (rate <= 0) throw std::runtime_error("espeak-ng: initialisation failed (is espeak-ng-data installed?)");
  if (espeak_SetVoiceByName("en-us") != EE_OK) throw std::runtime_error("espeak-ng: voice en-us not found");
  g_sample_rate_hz = rate;
  return rate;
}

// Short-time RMS from a prefix sum of squares.
class Energy {
 public:
  explicit Energy(std::span<const std::int16_t> s) : prefix_(s.size() + 1, 0.0) {
    for (std::size_t i = 0; i < s.size(); ++i) prefix_[i + 1] = prefix_[i] + double(s[i]) * s[i];
  }
  // RMS over [begin, end) clipped to the signal; 0 for an empty window.
  double rms(std::int64_t begin, std::int64_t end) const {
    const auto n = static_cast<std::int64_t>(prefix_.size()) - 1;
    begin = std::clamp<std::int64_t>(begin, 0, n);
    end = std::clamp<std::int64_t>(end, 0, n);
    if (end <= begin) return 0.0;
    return std::sqrt((prefix_[end] - prefix_[begin]) / double(end - begin));
  }

 private:
  std::vector<double> prefix_;
};

// Below this RMS (of full scale 32767) a stretch counts as silence, not as a sound to drop from.
constexpr double kSilenceRms = 100.0;

// Rule and detail come as "rule: detail".
InputError text_error(std::size_t offset, const std::string& rule_and_detail) {
  const std::size_t colon = rule_and_detail.find(": ");
  return InputError({"text", std::nullopt, offset}, rule_and_detail.substr(0, colon),
                    rule_and_detail.substr(colon + 2));
}

}  // namespace

std::vector<std::size_t> validate_text(std::string_view text) {
  if (text.size() > kMaxTextBytes) {
    throw text_error(kMaxTextBytes, "text-too-long: " + std::to_string(text.size()) +
                                        " bytes, limit " + std::to_string(kMaxTextBytes) +
                                        " (split the text)");
  }
  std::vector<std::size_t> offsets;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::size_t n = 0;
    char32_t cp = 0;
    if (c < 0x80) { n = 1; cp = c; }
    else if ((c & 0xE0) == 0xC0) { n = 2; cp = c & 0x1F; }
    else if ((c & 0xF0) == 0xE0) { n = 3; cp = c & 0x0F; }
    else if ((c & 0xF8) == 0xF0) { n = 4; cp = c & 0x07; }
    else throw text_error(i, "invalid-utf8: bad lead byte");
    if (i + n > text.size()) throw text_error(i, "invalid-utf8: truncated sequence");
    for (std::size_t k = 1; k < n; ++k) {
      const auto cc = static_cast<unsigned char>(text[i + k]);
      if ((cc & 0xC0) != 0x80) throw text_error(i, "invalid-utf8: bad continuation byte");
      cp = (cp << 6) | (cc & 0x3F);
    }
    static constexpr char32_t kMinForLength[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < kMinForLength[n]) throw text_error(i, "invalid-utf8: overlong encoding");
    if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) throw text_error(i, "invalid-utf8: not a scalar value");
    const bool control = (cp < 0x20 && cp != '\t' && cp != '\n' && cp != '\r') ||
                         (cp >= 0x7F && cp < 0xA0);
    if (control) throw text_error(i, "control-character: U+" + std::to_string(static_cast<unsigned>(cp)) + " (decimal)");
    offsets.push_back(i);
    i += n;
  }
  return offsets;
}

Closure find_closure(std::span<const std::int16_t> samples, SampleRate sample_rate,
                     std::int64_t region_begin, std::int64_t event_sample, std::int64_t region_end) {
  const std::int64_t rate = sample_rate.hz;
  const std::int64_t window = std::max<std::int64_t>(1, rate / 100);  // 10 ms
  const std::int64_t hop = std::max<std::int64_t>(1, rate / 400);     // 2.5 ms
  const auto size = static_cast<std::int64_t>(samples.size());
  region_begin = std::clamp<std::int64_t>(region_begin, 0, size);
  region_end = std::clamp<std::int64_t>(region_end, region_begin, size);
  event_sample = std::clamp(event_sample, region_begin, region_end);
  // Energy of the searched stretch only, so that segmenting a long text stays linear.
  const std::int64_t base = std::max<std::int64_t>(0, region_begin - window);
  const std::int64_t stop = std::min(size, region_end + window);
  const Energy energy(samples.subspan(static_cast<std::size_t>(base), static_cast<std::size_t>(stop - base)));
  const auto rms_at = [&](std::int64_t centre) {
    return energy.rms(centre - window / 2 - base, centre + window / 2 - base);
  };

  double reference = 0.0;
  for (std::int64_t c = region_begin; c < event_sample; c += hop) reference = std::max(reference, rms_at(c));
  if (reference < kSilenceRms) {
    // After silence the lips may close at any time; assume a typical 50 ms closure.
    return {std::max(region_begin, event_sample - rate / 20), event_sample};
  }
  const double threshold = 0.2 * reference;
  const std::int64_t first = std::max(region_begin, event_sample - rate / 100);
  const std::int64_t last = std::min(region_end, event_sample + rate / 25);
  std::int64_t anchor = -1;
  for (std::int64_t c = first; c < last; c += hop) {
    if (rms_at(c) < threshold) { anchor = c; break; }
  }
  if (anchor < 0) return {event_sample, event_sample};
  std::int64_t onset = anchor;
  while (onset - hop >= region_begin && rms_at(onset - hop) < threshold) onset -= hop;
  std::int64_t release = anchor;
  while (release + hop < region_end && rms_at(release + hop) < threshold) release += hop;
  // Window centre -> crossing sample: a step crosses half a window before the centre of the
  // first quiet window, a gradual decay at the centre; a quarter window splits the difference.
  onset = std::max(region_begin, onset - window / 4);
  release = std::min(region_end, release + window / 4);
  return {onset, std::max(release, onset)};
}

// espeak-ng's default speaking rate, words per minute.
constexpr double kDefaultWordsPerMinute = 175.0;

Speech speak(std::string_view text, const SpeakOptions& options) {
  const std::vector<std::size_t> char_offsets = validate_text(text);
  Speech speech;
  Collector collector;
  {
    std::lock_guard lock(espeak_mutex());
    speech.audio.sample_rate = SampleRate{ensure_espeak()};
    if (std::all_of(text.begin(), text.end(), [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; })) {
      return speech;
    }
    espeak_SetSynthCallback(collect);
    g_collector = &collector;
    const std::string buffer(text);  // NUL-terminated copy
    const int wpm = static_cast<int>(std::lround(std::clamp(kDefaultWordsPerMinute * options.rate_factor, 80.0, 450.0)));
    espeak_SetParameter(espeakRATE, wpm, 0);  // set on every call: espeak-ng keeps it between calls
    unsigned flags = espeakCHARS_UTF8 | (options.phoneme_input ? espeakPHONEMES : 0u);
    const espeak_ERROR status = espeak_Synth(buffer.c_str(), buffer.size() + 1, 0, POS_CHARACTER, 0,
                                             flags, nullptr, nullptr);
    espeak_Synchronize();
    g_collector = nullptr;
    if (status != EE_OK) throw std::runtime_error("espeak-ng: synthesis failed (status " + std::to_string(status) + ")");
  }
  speech.audio.samples = std::move(collector.samples);
  const auto total = static_cast<std::int64_t>(speech.audio.samples.size());

  // Phones from phoneme events; word membership from the word event that precedes them.
  struct SpokenPhone {
    TimedPhone timed;
    PhoneEvent event;
  };
  std::vector<SpokenPhone> spoken;
  int word_event = -1;
  std::vector<int> word_of_event;   // per word event: index into speech.words or -1 until used
  std::vector<const RawEvent*> word_events;
  for (const RawEvent& e : collector.events) {
    if (e.type == espeakEVENT_WORD) {
      word_events.push_back(&e);
      word_of_event.push_back(-1);
      word_event = static_cast<int>(word_events.size()) - 1;
      continue;
    }
    const Phone phone = phone_from_espeak(e.name, "espeak-ng phoneme event");
    const std::int64_t at = std::clamp<std::int64_t>(e.sample, 0, total);
    if (!spoken.empty() && at < spoken.back().event.event_sample) {
      throw std::runtime_error("espeak-ng: phoneme events out of order");
    }
    int word = kNoWord;
    if (phone != Phone::SIL && word_event >= 0) {
      if (word_of_event[word_event] < 0) {
        const RawEvent& w = *word_events[word_event];
        const auto first = static_cast<std::size_t>(std::max(0, w.text_position - 1));
        const std::size_t begin = first < char_offsets.size() ? char_offsets[first] : text.size();
        const std::size_t last = first + static_cast<std::size_t>(std::max(0, w.length));
        const std::size_t end = last < char_offsets.size() ? char_offsets[last] : text.size();
        word_of_event[word_event] = static_cast<int>(speech.words.size());
        speech.words.push_back({std::string(text.substr(begin, end - begin)), begin, at, at});
      }
      word = word_of_event[word_event];
    }
    spoken.push_back({{phone, at, at}, {at, at, word, e.name}});
  }
  // Contiguous segments: a leading silence if the first event is late; drop empty segments.
  if (!spoken.empty() && spoken.front().timed.start_sample > 0) {
    spoken.insert(spoken.begin(), {{Phone::SIL, 0, 0}, {0, 0, kNoWord, "_"}});
  }
  std::vector<SpokenPhone> kept;
  for (std::size_t i = 0; i < spoken.size(); ++i) {
    SpokenPhone p = spoken[i];
    p.timed.end_sample = i + 1 < spoken.size() ? spoken[i + 1].event.event_sample : total;
    if (p.timed.end_sample > p.timed.start_sample) kept.push_back(std::move(p));
  }
  // Closures: move the start of each closing phone back to where the audio goes quiet.
  for (std::size_t i = 1; i < kept.size(); ++i) {
    SpokenPhone& p = kept[i];
    if (!has_closure(p.timed.phone)) continue;
    TimedPhone& previous = kept[i - 1].timed;
    const Closure c = find_closure(speech.audio.samples, speech.audio.sample_rate,
                                   previous.start_sample + 1, p.event.event_sample, p.timed.end_sample);
    const std::int64_t onset = std::clamp(c.onset_sample, previous.start_sample + 1, p.timed.end_sample - 1);
    p.timed.start_sample = onset;
    p.event.release_sample = std::max(c.release_sample, onset);
    previous.end_sample = onset;
  }
  speech.phones.reserve(kept.size());
  speech.events.reserve(kept.size());
  for (SpokenPhone& p : kept) {
    speech.phones.push_back(p.timed);
    speech.events.push_back(std::move(p.event));
  }
  std::vector<bool> seen(speech.words.size(), false);
  for (std::size_t i = 0; i < speech.phones.size(); ++i) {
    const int word = speech.events[i].word;
    if (word == kNoWord) continue;
    TimedWord& w = speech.words[static_cast<std::size_t>(word)];
    if (!seen[static_cast<std::size_t>(word)]) w.start_sample = speech.phones[i].start_sample;
    seen[static_cast<std::size_t>(word)] = true;
    w.end_sample = speech.phones[i].end_sample;
  }
  return speech;
}

}  // namespace fapcast
