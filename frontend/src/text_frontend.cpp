#include "fapcast/frontend/text_frontend.hpp"

#include "fapcast/frontend/espeak_language.hpp"

#include <espeak-ng/speak_lib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <mutex>
#include <stdexcept>

#include "fapcast/core/huge_pages.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/utf8.hpp"
#include "fapcast/phonetics/ipa_features.hpp"
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
bool g_ipa_mode = false;           // guarded by espeak_mutex(): phoneme events name IPA
std::string g_voice;               // guarded by espeak_mutex(): the voice last selected

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

// Initialises espeak-ng (caller holds the mutex) with phoneme events as mnemonics or as IPA,
// again when the mode changes, and returns its sample rate.
int ensure_espeak(bool ipa) {
  if (g_sample_rate_hz > 0 && g_ipa_mode == ipa) return g_sample_rate_hz;
  const int options = espeakINITIALIZE_PHONEME_EVENTS | espeakINITIALIZE_DONT_EXIT |
                      (ipa ? espeakINITIALIZE_PHONEME_IPA : 0);
  const int rate = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr, options);
  if (rate <= 0) throw std::runtime_error("espeak-ng: initialisation failed (is espeak-ng-data installed?)");
  g_sample_rate_hz = rate;
  g_ipa_mode = ipa;
  g_voice.clear();
  return rate;
}

// Selects an espeak-ng voice "language[+variant]" (caller holds the mutex, espeak initialised).
void select_voice(const std::string& voice) {
  if (voice == g_voice) return;
  if (espeak_SetVoiceByName(voice.c_str()) != EE_OK) {
    g_voice.clear();
    throw std::invalid_argument("espeak-ng: voice '" + voice + "' not found");
  }
  g_voice = voice;
}

// The phone of an en-us mnemonic event. Text in another script makes espeak-ng switch language
// by itself ("(ru)" ... "(en)"): those events name the other language's mnemonics (ASCII, close
// to Kirshenbaum's IPA), which go through the IPA features; a switch event is no phone.
std::optional<Phone> phone_from_mnemonic(const std::string& name) {
  const auto* row = std::find_if(kEspeakMap.begin(), kEspeakMap.end(), [&](const auto& r) { return r.first == name; });
  if (row != kEspeakMap.end()) return row->second;
  return phone_from_ipa_features(name, "espeak-ng phoneme event (language en-us, switched by script)");
}

// A phoneme name cut by espeak-ng's 8-byte event field may end in half a UTF-8 sequence.
std::string_view whole_code_points(std::string_view name) {
  std::size_t lead = name.size();
  while (lead > 0 && (static_cast<unsigned char>(name[lead - 1]) & 0xC0) == 0x80) --lead;
  if (lead == 0) return name;
  const std::size_t n = std::max<std::size_t>(utf8_sequence_length(name[lead - 1]), 1);
  return name.size() - (lead - 1) < n ? name.substr(0, lead - 1) : name;
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
InputError text_error(const std::string& source, std::size_t offset, const std::string& rule_and_detail) {
  const std::size_t colon = rule_and_detail.find(": ");
  return InputError({source, std::nullopt, offset}, rule_and_detail.substr(0, colon),
                    rule_and_detail.substr(colon + 2));
}

}  // namespace

namespace {

// Checks the input rules over `text`, which starts at byte `base` of the input named `source`; appends each
// code point's offset (relative to `text`) to `offsets` unless it is null.
void scan_text(std::string_view text, const std::string& source, std::size_t base, std::vector<std::size_t>* offsets) {
  std::size_t i = 0;
  while (i < text.size()) {
    const Utf8CodePoint decoded = decode_utf8_at(text, i);
    if (decoded.error) throw text_error(source, base + i, std::string("invalid-utf8: ") + utf8_error_text(*decoded.error));
    const char32_t cp = decoded.value;
    const std::size_t n = decoded.bytes;
    const bool control = (cp < 0x20 && cp != '\t' && cp != '\n' && cp != '\r') ||
                         (cp >= 0x7F && cp < 0xA0);
    if (control) throw text_error(source, base + i, "control-character: U+" + std::to_string(static_cast<unsigned>(cp)) + " (decimal)");
    if (offsets != nullptr) offsets->push_back(i);
    i += n;
  }
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

std::vector<std::size_t> validate_text(std::string_view text) {
  std::vector<std::size_t> offsets;
  scan_text(text, "text", 0, &offsets);
  return offsets;
}

std::vector<std::size_t> chunk_offsets(std::string_view text, std::size_t max_bytes) {
  max_bytes = std::max<std::size_t>(max_bytes, 4);  // room for one code point
  std::vector<std::size_t> starts;
  // Sentence boundaries: after . ! ? or a line break when white space follows; after the full
  // stops of scripts written without spaces (。！？ Chinese and Japanese, । Devanagari, ؟ ۔ Arabic
  // and Urdu) with or without it.
  const auto sentence_end_before = [&](std::size_t at) {  // after . ! ? or a line break: at is white space
    if (at == 0 || at >= text.size() || !is_space(text[at])) return false;
    const char last = text[at - 1];
    return last == '.' || last == '!' || last == '?' || last == '\n';
  };
  const auto script_stop_before = [&](std::size_t at) {  // a boundary between at-1 and at
    const std::string_view tail = text.substr(0, at);
    for (const std::string_view stop : {"\u3002", "\uFF01", "\uFF1F", "\u0964", "\u061F", "\u06D4"})
      if (tail.ends_with(stop)) return true;
    return false;
  };
  std::size_t start = 0;
  while (start < text.size()) {
    starts.push_back(start);
    if (text.size() - start <= max_bytes) break;
    const std::size_t limit = start + max_bytes;  // the chunk ends at or before this byte
    std::size_t cut = 0;
    for (std::size_t at = limit - 1; at > start; --at) {  // cut after the white space
      if (script_stop_before(at)) { cut = at < text.size() && is_space(text[at]) ? at + 1 : at; break; }
      if (sentence_end_before(at)) { cut = at + 1; break; }
    }
    if (cut == 0) {
      for (std::size_t at = limit; at > start; --at) {
        if (is_space(text[at - 1])) { cut = at; break; }
      }
    }
    if (cut == 0) {
      cut = limit;
      while (cut > start + 1 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    }
    start = cut;
  }
  return starts;
}

std::vector<EspeakLanguage> espeak_languages() {
  std::lock_guard lock(espeak_mutex());
  ensure_espeak(g_ipa_mode);
  std::vector<EspeakLanguage> out;
  for (const espeak_VOICE** v = espeak_ListVoices(nullptr); v != nullptr && *v != nullptr; ++v) {
    // languages: a priority byte, then a NUL-terminated code, repeated; an empty code ends it.
    for (const char* l = (*v)->languages; l != nullptr && l[0] != 0 && l[1] != 0; l += std::strlen(l + 1) + 2) {
      const std::string code(l + 1);
      if (std::none_of(out.begin(), out.end(), [&](const EspeakLanguage& e) { return e.code == code; })) {
        out.push_back({code, (*v)->name != nullptr ? (*v)->name : ""});
      }
    }
  }
  return out;
}

std::vector<std::string> espeak_variants() {
  std::lock_guard lock(espeak_mutex());
  ensure_espeak(g_ipa_mode);
  espeak_VOICE spec{};
  spec.languages = "variant";
  std::vector<std::string> out;
  for (const espeak_VOICE** v = espeak_ListVoices(&spec); v != nullptr && *v != nullptr; ++v) {
    const std::string_view id = (*v)->identifier != nullptr ? (*v)->identifier : "";
    const std::size_t slash = id.rfind('/');
    out.emplace_back(slash == std::string_view::npos ? id : id.substr(slash + 1));
  }
  return out;
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

namespace {

// Seconds of speech espeak-ng makes of a byte of text at its default rate, with room to spare:
// the page of tests/data/text gives 0.054 (158 s of 2,913 bytes).
constexpr double kSpeechSecondsPerTextByte = 0.07;

// One espeak_Synth call over `text`, which starts at byte `base` of the input.
// `voice` is what espeak_SetVoiceByName selects ("en-us", "Russian+f2"). The audio is collected
// into `samples` (emptied; its capacity kept, and raised to what the text is likely to need):
// the audio is not copied as the buffer grows, nor its pages faulted in again chunk after chunk
// when the caller hands the last chunk's buffer back.
Speech speak_chunk(std::string_view text, std::size_t base, const SpeakOptions& options, const std::string& voice,
                   std::vector<std::int16_t> samples = {}) {
  std::vector<std::size_t> char_offsets;
  scan_text(text, options.source, base, &char_offsets);
  const bool ipa = options.language != kDefaultLanguage;
  const std::string source = "espeak-ng phoneme event (language " + options.language + ")";
  Speech speech;
  Collector collector;
  {
    std::lock_guard lock(espeak_mutex());
    speech.audio.sample_rate = SampleRate{ensure_espeak(ipa)};
    select_voice(voice);
    if (std::all_of(text.begin(), text.end(), is_space)) return speech;
    espeak_SetSynthCallback(collect);
    collector.samples = std::move(samples);
    collector.samples.clear();
    const int wpm = static_cast<int>(std::lround(std::clamp(kDefaultWordsPerMinute * options.rate_factor, 80.0, 450.0)));
    const double expected_s = kSpeechSecondsPerTextByte * static_cast<double>(text.size()) * kDefaultWordsPerMinute / wpm;
    collector.samples.reserve(std::max(collector.samples.capacity(),
                                       static_cast<std::size_t>(expected_s * speech.audio.sample_rate.hz)));
    advise_huge_pages(collector.samples);  // a page's speech is 7 MB written once: 1,700 page faults otherwise
    g_collector = &collector;
    const std::string buffer(text);  // NUL-terminated copy
    espeak_SetParameter(espeakRATE, wpm, 0);  // set on every call: espeak-ng keeps it between calls
    const unsigned flags = espeakCHARS_UTF8 | (options.phoneme_input ? espeakPHONEMES : 0u) |
                           (options.ssml ? espeakSSML : 0u);
    const espeak_ERROR status = espeak_Synth(buffer.c_str(), buffer.size() + 1, 0, POS_CHARACTER, 0,
                                             flags, nullptr, nullptr);
    espeak_Synchronize();
    g_collector = nullptr;
    // espeak-ng switched language by itself ("(ru)"): it may not come back to the same voice
    // state, so the next call selects the voice again.
    if (std::any_of(collector.events.begin(), collector.events.end(),
                    [](const RawEvent& e) { return e.name.starts_with('('); })) {
      g_voice.clear();
    }
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
    const std::optional<Phone> mapped = ipa ? phone_from_ipa_features(whole_code_points(e.name), source)
                                            : phone_from_mnemonic(e.name);
    if (!mapped) continue;  // a language switch or a lone modifier: the phone before goes on
    const Phone phone = *mapped;
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
        speech.words.push_back({std::string(text.substr(begin, end - begin)), base + begin, at, at});
      }
      word = word_of_event[word_event];
    }
    spoken.push_back({{phone, at, at}, {at, at, word, e.name}});
  }
  // Contiguous segments: a leading silence if the first event is late; drop empty segments.
  if (!spoken.empty() && spoken.front().timed.start_sample > 0) {
    spoken.insert(spoken.begin(), {{Phone::SIL, 0, 0}, {0, 0, kNoWord, "_"}});
  }
  for (std::size_t i = 0; i < spoken.size(); ++i)
    spoken[i].timed.end_sample = i + 1 < spoken.size() ? spoken[i + 1].event.event_sample : total;
  // espeak-ng gives some phones no samples of their own: an /l/ or /r/ after a vowel before a
  // pause or a voiceless fricative ("all", "yourself") is synthesised inside the vowel's segment,
  // and its event shares the next phone's sample. Such a run of phones takes the later half of the
  // segment before it, in equal shares, so the phone is kept; an empty silence, or an empty phone
  // with nothing before it, is dropped.
  for (std::size_t i = 1; i < spoken.size(); ++i) {
    if (spoken[i].timed.phone == Phone::SIL || spoken[i].timed.end_sample > spoken[i].timed.start_sample) continue;
    std::size_t run_end = i;  // [i, run_end): the empty phones after spoken[i - 1]
    while (run_end < spoken.size() && spoken[run_end].timed.phone != Phone::SIL &&
           spoken[run_end].timed.end_sample == spoken[run_end].timed.start_sample)
      ++run_end;
    TimedPhone& before = spoken[i - 1].timed;
    const std::int64_t length = before.end_sample - before.start_sample;
    const auto shares = static_cast<std::int64_t>(run_end - i);
    if (length < 2 * shares) { i = run_end - 1; continue; }  // too short to share: dropped below
    const std::int64_t split = before.start_sample + length / 2;
    const std::int64_t share = (before.end_sample - split) / shares;
    before.end_sample = split;
    for (std::size_t k = i; k < run_end; ++k) {
      const auto n = static_cast<std::int64_t>(k - i);
      spoken[k].timed.start_sample = split + n * share;
      spoken[k].timed.end_sample = k + 1 < run_end ? split + (n + 1) * share : spoken[run_end - 1].timed.end_sample;
      spoken[k].event.release_sample = spoken[k].timed.start_sample;
    }
    i = run_end - 1;
  }
  std::vector<SpokenPhone> kept;
  for (SpokenPhone& p : spoken)
    if (p.timed.end_sample > p.timed.start_sample) kept.push_back(std::move(p));
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

// Appends `part` to `all`: samples, phones and words shifted; a silence across the join is one.
void append(Speech& all, Speech&& part) {
  const auto offset = static_cast<std::int64_t>(all.audio.samples.size());
  std::vector<std::int16_t> samples = std::move(part.audio.samples);
  if (!append_timing(all, std::move(part), offset)) return;
  if (all.audio.samples.empty()) {
    all.audio.samples = std::move(samples);
  } else {
    all.audio.samples.insert(all.audio.samples.end(), samples.begin(), samples.end());
  }
}

// The installed languages and variants, listed once (espeak_ListVoices reads every voice file).
const std::vector<EspeakLanguage>& cached_languages() {
  static const std::vector<EspeakLanguage> languages = espeak_languages();
  return languages;
}
const std::vector<std::string>& cached_variants() {
  static const std::vector<std::string> variants = espeak_variants();
  return variants;
}

}  // namespace

bool espeak_language_installed(std::string_view code) {
  const auto& languages = cached_languages();
  return std::any_of(languages.begin(), languages.end(), [&](const EspeakLanguage& l) { return l.code == code; });
}

bool append_timing(Speech& all, Speech&& part, std::int64_t offset) {
  if (part.phones.empty()) return false;
  if (all.audio.sample_rate.hz == 0) all.audio.sample_rate = part.audio.sample_rate;
  const auto word_base = static_cast<int>(all.words.size());
  std::size_t first = 0;
  if (!all.phones.empty() && all.phones.back().phone == Phone::SIL && part.phones.front().phone == Phone::SIL) {
    all.phones.back().end_sample = part.phones.front().end_sample + offset;
    first = 1;
  }
  for (std::size_t i = first; i < part.phones.size(); ++i) {
    TimedPhone p = part.phones[i];
    p.start_sample += offset;
    p.end_sample += offset;
    all.phones.push_back(p);
    PhoneEvent e = std::move(part.events[i]);
    e.event_sample += offset;
    e.release_sample += offset;
    if (e.word != kNoWord) e.word += word_base;
    all.events.push_back(std::move(e));
  }
  for (TimedWord& w : part.words) {
    w.start_sample += offset;
    w.end_sample += offset;
    all.words.push_back(std::move(w));
  }
  return true;
}

void speak_chunks(std::string_view text, const SpeakOptions& options, const std::function<void(Speech&&)>& sink) {
  scan_text(text, options.source, 0, nullptr);  // the whole input first: a bad byte fails before any synthesis
  // A language code selects the first voice that lists it (by its name: a code such as en-gb or
  // zh is listed by a voice whose file has another name).
  std::string voice(kDefaultLanguage);
  if (options.language != kDefaultLanguage) {
    const auto& languages = cached_languages();
    const auto found = std::find_if(languages.begin(), languages.end(),
                                    [&](const EspeakLanguage& l) { return l.code == options.language; });
    if (found == languages.end()) {
      throw std::invalid_argument("espeak-ng: unknown language '" + options.language +
                                  "' (`espeak-ng --voices` lists the installed ones)");
    }
    voice = found->name;
  }
  if (!options.variant.empty()) {
    const auto& variants = cached_variants();
    if (std::find(variants.begin(), variants.end(), options.variant) == variants.end()) {
      throw std::invalid_argument("espeak-ng: unknown voice variant '" + options.variant +
                                  "' (`espeak-ng --voices=variant` lists the installed ones)");
    }
  }
  if (!options.variant.empty()) voice += "+" + options.variant;
  if (options.ssml || text.size() <= kChunkBytes) {
    sink(speak_chunk(text, 0, options, voice));
    return;
  }
  const std::vector<std::size_t> starts = chunk_offsets(text, kChunkBytes);
  std::vector<std::int16_t> samples;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const std::size_t end = i + 1 < starts.size() ? starts[i + 1] : text.size();
    Speech part = speak_chunk(text.substr(starts[i], end - starts[i]), starts[i], options, voice, std::move(samples));
    sink(std::move(part));
    samples = std::move(part.audio.samples);  // what the sink left of them (nothing if it took them)
  }
}

Speech speak(std::string_view text, const SpeakOptions& options) {
  Speech all;
  speak_chunks(text, options, [&all](Speech&& part) {
    if (all.audio.sample_rate.hz == 0) all.audio.sample_rate = part.audio.sample_rate;
    append(all, std::move(part));
  });
  return all;
}

}  // namespace fapcast
