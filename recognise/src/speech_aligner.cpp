#include "fapcast/recognise/speech_aligner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "decoder.hpp"
#include "fapcast/recognise/resample.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/frontend/text_frontend.hpp"
#include "fapcast/phonetics/phone.hpp"

namespace fapcast {

namespace {

// A phone of transcript word i is the one-phone dictionary word "~PH@k", k = i mod kTags; a
// phone of the garbage loop standing in for word i is "#PH@k". The word a segment belongs to is
// read back from k: the path never skips kTags words in a row (spec/recognise.md, "Grammar").
constexpr std::size_t kTags = 8;

// The garbage loop of the mismatch diagnosis (100 frames per second): entering it instead of a
// word costs 1e-30, each of its phones 1e-10. On the 16 real recordings of spec/recognise.md: no
// correct transcript diagnosed as mismatched.
constexpr double kGarbageEnter = 1e-30;
constexpr double kGarbagePhone = 1e-10;

// A recording whose phones score below this on average (nats per frame) is refused as
// "low-confidence" (spec/recognise.md: correct recordings -1.2 .. -2.6; header rate 8 kHz for 16 kHz
// speech -3.8).
constexpr double kLowUtteranceScore = -3.0;

std::vector<Phone> phone_set() {
  std::vector<Phone> out;
  for (std::size_t i = 0; i < kPhoneCount; ++i)
    if (static_cast<Phone>(i) != Phone::SIL) out.push_back(static_cast<Phone>(i));
  return out;
}

std::string tagged(char kind, Phone p, std::size_t word) {
  return std::string(1, kind) + std::string(arpabet(p)) + "@" + std::to_string(word % kTags);
}

std::vector<std::pair<std::string, std::string>> phone_words() {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t k = 0; k < kTags; ++k)
    for (Phone p : phone_set())
      for (char kind : {'~', '#'}) out.emplace_back(tagged(kind, p, k), std::string(arpabet(p)));
  return out;
}

std::vector<Phone> parse_pronunciation(const std::string& phones) {
  std::vector<Phone> out;
  std::istringstream in(phones);
  for (std::string s; in >> s;) out.push_back(parse_arpabet(s, "pocketsphinx dictionary").phone);
  return out;
}

std::string pronunciation_string(const std::vector<Phone>& phones) {
  std::string s;
  for (Phone p : phones) s += (s.empty() ? "" : " ") + std::string(arpabet(p));
  return s;
}

// One transcript word: its dictionary entries ("was", "was(2)") and their phones.
struct WordEntry {
  std::vector<std::string> keys;
  std::vector<std::vector<Phone>> variants;
};

std::string seconds(std::int64_t sample, std::int64_t rate) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f s", static_cast<double>(sample) / static_cast<double>(rate));
  return buf;
}

bool is_noise(const std::string& w) { return w == "[NOISE]" || w == "[SPEECH]" || (w.size() > 2 && w.front() == '+'); }
bool is_silence(const std::string& w) { return w == "<sil>" || w == "<s>" || w == "</s>" || w == "SIL"; }

}  // namespace

struct SpeechAligner::Impl {
  AlignerSettings settings;
  std::optional<Decoder> phones;  // the alignment (200 fps, GMM every 2nd frame, by default)
  std::optional<Decoder> words;   // 100 fps: the diagnosis of a mismatch (garbage loops)

  Decoder& phone_decoder() {
    if (!phones) {
      const int fps = settings.frames_per_second;
      phones.emplace(DecoderSettings{.frames_per_second = fps, .gmm_every = fps == 200 ? 2 : 1});
      phones->add_words(phone_words());
    }
    return *phones;
  }
  Decoder& word_decoder() {
    if (!words) {
      words.emplace(DecoderSettings{.frames_per_second = 100, .gmm_every = 1});
      words->add_words(phone_words());
    }
    return *words;
  }

  // Dictionary entries of every word; words the dictionary lacks get espeak-ng's pronunciation,
  // added to both decoders under their key.
  std::vector<WordEntry> entries(const Transcript& t) {
    Decoder& d = phone_decoder();
    std::vector<WordEntry> out(t.words.size());
    std::optional<Speech> spoken;
    std::vector<std::pair<std::string, std::string>> added;
    for (std::size_t i = 0; i < t.words.size(); ++i) {
      const auto& w = t.words[i];
      std::vector<std::string> prons = d.pronunciations(w.key);
      for (std::size_t k = 0; k < prons.size(); ++k) {
        out[i].keys.push_back(k == 0 ? w.key : w.key + "(" + std::to_string(k + 1) + ")");
        out[i].variants.push_back(parse_pronunciation(prons[k]));
      }
      if (!prons.empty()) continue;
      if (!spoken) spoken = speak(t.text);
      std::vector<Phone> ph;
      for (std::size_t p = 0; p < spoken->phones.size(); ++p) {
        const int wi = spoken->events[p].word;
        if (wi < 0 || spoken->phones[p].phone == Phone::SIL) continue;
        const auto& sw = spoken->words[static_cast<std::size_t>(wi)];
        if (sw.byte_offset >= w.byte_offset && sw.byte_offset < w.byte_offset + w.text.size())
          ph.push_back(spoken->phones[p].phone);
      }
      if (ph.empty())
        throw InputError({"transcript", std::nullopt, w.byte_offset}, "no-pronunciation",
                         "espeak-ng says nothing for '" + w.text + "'");
      out[i].keys.push_back(w.key);
      out[i].variants.push_back(ph);
      added.emplace_back(w.key, pronunciation_string(ph));
    }
    if (!added.empty()) {
      d.add_words(added);
      if (words) words->add_words(added);
    }
    return out;
  }
};

namespace {

// The phone grammar: word i's variants run in parallel from boundary state i to i + 1; pauses
// (silence, noise) may repeat at every boundary. With `garbage`, each word may instead be a loop
// of garbage phones (or nothing: a word the recording leaves out).
Grammar phone_grammar(const std::vector<WordEntry>& entries, bool garbage) {
  Grammar g;
  const int n = static_cast<int>(entries.size());
  g.start = 0;
  g.final = n;
  int next = n + 1;
  for (int i = 0; i < n; ++i) {
    const double p = 1.0 / static_cast<double>(entries[static_cast<std::size_t>(i)].variants.size());
    for (const auto& v : entries[static_cast<std::size_t>(i)].variants) {
      int from = i;
      for (std::size_t k = 0; k < v.size(); ++k) {
        const int to = k + 1 == v.size() ? i + 1 : next++;
        g.arcs.push_back({from, to, tagged('~', v[k], static_cast<std::size_t>(i)), k == 0 ? p : 1.0});
        from = to;
      }
    }
    if (garbage) {
      const int loop = next++;
      g.arcs.push_back({i, loop, "", kGarbageEnter});
      for (Phone ph : phone_set()) g.arcs.push_back({loop, loop, tagged('#', ph, static_cast<std::size_t>(i)), kGarbagePhone});
      g.arcs.push_back({loop, i + 1, "", 1.0});
      // the recording stops before word i (at 0: has none of them): one null arc to the end, not a chain of skipped
      // words (each skip costs kGarbageEnter, so a chain falls out of the beam)
      g.arcs.push_back({i, n, "", kGarbageEnter});
    }
  }
  g.states = next;
  for (int i = 0; i <= n; ++i) g.pause_states.push_back(i);
  return g;
}

// The word grammar: the same words as whole dictionary entries (cross-word triphones).
Grammar word_grammar(const std::vector<WordEntry>& entries) {
  Grammar g;
  const int n = static_cast<int>(entries.size());
  g.states = n + 1;
  g.final = n;
  for (int i = 0; i < n; ++i)
    for (const auto& key : entries[static_cast<std::size_t>(i)].keys)
      g.arcs.push_back({i, i + 1, key, 1.0 / static_cast<double>(entries[static_cast<std::size_t>(i)].keys.size())});
  for (int i = 0; i <= n; ++i) g.pause_states.push_back(i);
  return g;
}

struct PathReader {
  const Decoder& decoder;
  std::int64_t rate;
  std::int64_t samples;

  std::int64_t to_sample(int frame) const {
    const std::int64_t s16 = decoder.frame_start_sample(frame);
    return std::clamp<std::int64_t>((s16 * rate + kDecoderSampleRateHz / 2) / kDecoderSampleRateHz, 0, samples);
  }

  // Segments from a phone-grammar path; `words` gets one entry per transcript word.
  SpeechAlignment read(const std::vector<DecodedSegment>& path, const Transcript& t) const {
    SpeechAlignment a;
    a.sample_rate = SampleRate{rate};
    a.samples = samples;
    std::size_t word = 0;
    bool started = false;
    for (const auto& s : path) {
      SpeechSegment g;
      g.start_sample = to_sample(s.start_frame);
      g.end_sample = to_sample(s.end_frame);
      g.score_per_frame = s.score_per_frame;
      if ((s.word.front() == '~' || s.word.front() == '#') && s.word.find('@') != std::string::npos) {
        const auto at = s.word.rfind('@');
        const std::size_t tag = std::stoul(s.word.substr(at + 1));
        std::size_t w = started ? word : 0;
        while (w % kTags != tag) ++w;
        word = w;
        started = true;
        g.word = static_cast<int>(word);
        if (s.word.front() == '~') {
          g.kind = SpeechSegmentKind::phone;
          g.phone = parse_arpabet(s.word.substr(1, at - 1), "pocketsphinx path").phone;
        } else {
          g.kind = SpeechSegmentKind::unmatched;
        }
      } else {
        g.kind = is_noise(s.word) ? SpeechSegmentKind::noise : SpeechSegmentKind::silence;
      }
      // one segment per pause, per unmatched stretch
      if (!a.segments.empty() && g.kind != SpeechSegmentKind::phone && a.segments.back().kind == g.kind &&
          a.segments.back().word == g.word) {
        a.segments.back().end_sample = g.end_sample;
        continue;
      }
      a.segments.push_back(g);
    }
    if (!a.segments.empty()) {
      a.segments.front().start_sample = 0;
      a.segments.back().end_sample = samples;
    }
    for (std::size_t i = 0; i < t.words.size(); ++i) a.words.push_back({t.words[i].text, t.words[i].byte_offset});
    return a;
  }
};

// Word spans and scores from their segments.
void finish_words(SpeechAlignment& a) {
  for (std::size_t w = 0; w < a.words.size(); ++w) {
    auto& word = a.words[w];
    double sum = 0, frames = 0;
    bool first = true;
    for (const auto& s : a.segments) {
      if (s.word != static_cast<int>(w)) continue;
      if (first) word.start_sample = s.start_sample;
      first = false;
      word.end_sample = s.end_sample;
      if (s.kind == SpeechSegmentKind::phone) {
        const double f = static_cast<double>(s.end_sample - s.start_sample);
        sum += s.score_per_frame * f;
        frames += f;
      }
    }
    word.score_per_frame = frames > 0 ? sum / frames : -1e9;
    word.low_confidence = word.score_per_frame < kLowConfidenceScore;
  }
}

// Moves each word's first and last phone edge to where `edges` (a word-grammar path) puts the
// word, when that stays inside the neighbouring segments.
void snap_word_edges(SpeechAlignment& a, const std::vector<std::pair<std::int64_t, std::int64_t>>& edges,
                     std::int64_t min_gap) {
  auto& seg = a.segments;
  for (std::size_t w = 0; w < edges.size(); ++w) {
    int first = -1, last = -1;
    for (std::size_t i = 0; i < seg.size(); ++i)
      if (seg[i].word == static_cast<int>(w)) {
        if (first < 0) first = static_cast<int>(i);
        last = static_cast<int>(i);
      }
    if (first < 0) continue;
    const auto [start, end] = edges[w];
    if (first > 0 && start > seg[first - 1].start_sample + min_gap && start < seg[first].end_sample - min_gap)
      seg[first].start_sample = seg[first - 1].end_sample = start;
    if (last + 1 < static_cast<int>(seg.size()) && end > seg[last].start_sample + min_gap &&
        end < seg[last + 1].end_sample - min_gap)
      seg[last].end_sample = seg[last + 1].start_sample = end;
  }
}

std::vector<std::pair<std::int64_t, std::int64_t>> word_edges(const std::vector<DecodedSegment>& path,
                                                              const PathReader& reader) {
  std::vector<std::pair<std::int64_t, std::int64_t>> out;
  for (const auto& s : path)
    if (!is_silence(s.word) && !is_noise(s.word))
      out.emplace_back(reader.to_sample(s.start_frame), reader.to_sample(s.end_frame));
  return out;
}

void check_length(const Audio& speech, const std::string& source) {
  if (speech.sample_rate.hz < kMinSpeechRate.hz || speech.sample_rate.hz > kMaxSpeechRate.hz)
    throw InputError({source, std::nullopt, std::nullopt}, "sample-rate",
                     std::to_string(speech.sample_rate.hz) + " Hz: the aligner takes 8000..192000 Hz");
  if (speech.instants() < speech.sample_rate.hz / 10)
    throw InputError({source, std::nullopt, std::nullopt}, "speech-empty",
                     "the recording is shorter than 0.1 s");
}

}  // namespace

SpeechAligner::SpeechAligner(const AlignerSettings& settings) : impl_(std::make_unique<Impl>()) {
  if (settings.frames_per_second != 100 && settings.frames_per_second != 200)
    throw std::invalid_argument("SpeechAligner: frames_per_second must be 100 or 200");
  impl_->settings = settings;
}

SpeechAligner::~SpeechAligner() = default;

SpeechAlignment SpeechAligner::align(const Audio& speech, const Transcript& transcript, const std::string& source) {
  check_length(speech, source);
  const Audio s16 = resample_mono(speech, SampleRate{kDecoderSampleRateHz});
  const std::int64_t rate = speech.sample_rate.hz, samples = speech.instants();
  const std::vector<WordEntry> entries = impl_->entries(transcript);
  Decoder& pd = impl_->phone_decoder();
  const PathReader reader{pd, rate, samples};

  // Where a recording diverges from its transcript: the garbage loop at 100 fps.
  auto diagnose = [&]() -> std::optional<SpeechAlignment> {
    Decoder& wd = impl_->word_decoder();
    const PathReader wr{wd, rate, samples};
    const auto path = wd.decode(phone_grammar(entries, true), s16.samples);
    if (!path) throw InputError({source, std::nullopt, std::nullopt}, "no-speech", "no path through the transcript fits the recording, even with words left out (another recording's text, silence or noise?)");
    SpeechAlignment d = wr.read(*path, transcript);
    std::vector<bool> matched(transcript.words.size(), false), garbage(transcript.words.size(), false);
    for (const auto& g : d.segments) {
      if (g.word < 0) continue;
      (g.kind == SpeechSegmentKind::phone ? matched : garbage)[static_cast<std::size_t>(g.word)] = true;
    }
    if (std::none_of(matched.begin(), matched.end(), [](bool m) { return m; }))
      throw InputError({source, std::nullopt, std::nullopt}, "no-speech", "no word of the transcript was found in the recording (silence, noise, another recording?)");
    for (std::size_t w = 0; w < matched.size(); ++w) {
      if (matched[w] && !garbage[w]) continue;
      std::int64_t at = 0;  // where the recording leaves the transcript: the garbage, or the end of the last word found
      for (const auto& g : d.segments)
        if (g.word == static_cast<int>(w) && g.kind == SpeechSegmentKind::unmatched) { at = g.start_sample; break; }
        else if (g.word >= 0 && g.word < static_cast<int>(w)) at = g.end_sample;
      const auto& tw = transcript.words[w];
      throw InputError({source, std::nullopt, std::nullopt}, "transcript-mismatch",
                       seconds(at, rate) + ": the recording diverges from the transcript at word " + std::to_string(w + 1) +
                           " '" + tw.text + "' (byte " + std::to_string(tw.byte_offset) + ")" +
                           (matched[w] ? "" : ": not found in the recording"));
    }
    finish_words(d);
    return d;
  };

  const auto path = pd.decode(phone_grammar(entries, false), s16.samples);
  SpeechAlignment a;
  if (path) {
    a = reader.read(*path, transcript);
    if (impl_->settings.word_edges)
      if (const auto wpath = pd.decode(word_grammar(entries), s16.samples)) {
        const auto edges = word_edges(*wpath, reader);
        if (edges.size() == transcript.words.size()) snap_word_edges(a, edges, rate / 200);
      }
    finish_words(a);
    if (std::any_of(a.words.begin(), a.words.end(), [](const SpeechWord& w) { return w.low_confidence; })) diagnose();
  } else {
    a = *diagnose();  // throws, or aligns at 100 fps when every word is there; then checked as any alignment
  }
  double sum = 0, frames = 0;
  for (const auto& g : a.segments)
    if (g.kind == SpeechSegmentKind::phone) {
      sum += g.score_per_frame * static_cast<double>(g.end_sample - g.start_sample);
      frames += static_cast<double>(g.end_sample - g.start_sample);
    }
  if (frames > 0 && sum / frames < kLowUtteranceScore) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "the recording matches its transcript poorly (mean score %.2f per frame, below %.1f): is its sample rate (%lld Hz) right, is it English?",
                  sum / frames, kLowUtteranceScore, static_cast<long long>(rate));
    throw InputError({source, std::nullopt, std::nullopt}, "low-confidence", buf);
  }
  return a;
}

SpeechAlignment SpeechAligner::recognise(const Audio& speech, const std::string& source) {
  check_length(speech, source);
  const Audio s16 = resample_mono(speech, SampleRate{kDecoderSampleRateHz});
  const std::int64_t rate = speech.sample_rate.hz, samples = speech.instants();
  Decoder& wd = impl_->word_decoder();
  const PathReader wr{wd, rate, samples};
  const std::vector<DecodedSegment> heard = wd.recognise_words(s16.samples);
  // the words heard, as a transcript of dictionary keys ("was(2)" is the word "was")
  Transcript t;
  std::vector<double> scores;  // the recogniser's, per word
  for (const auto& s : heard) {
    if (is_silence(s.word) || is_noise(s.word)) continue;
    scores.push_back(s.score_per_frame);
    const std::string word = s.word.substr(0, s.word.find('('));
    if (!t.text.empty()) t.text += ' ';
    t.words.push_back({word, word, t.text.size()});
    t.text += word;
  }
  if (t.words.empty())
    throw InputError({source, std::nullopt, std::nullopt}, "no-speech",
                     "no word was heard in the recording (silence or noise?)");
  const auto edges = word_edges(heard, wr);
  const std::vector<WordEntry> entries = impl_->entries(t);
  Decoder& pd = impl_->phone_decoder();
  const PathReader reader{pd, rate, samples};
  SpeechAlignment a;
  if (const auto path = pd.decode(phone_grammar(entries, false), s16.samples)) {
    a = reader.read(*path, t);
    snap_word_edges(a, edges, rate / 200);
  } else {  // no phone path through the words heard: each word's first pronunciation spread over it
    a.sample_rate = speech.sample_rate;
    a.samples = samples;
    std::int64_t at = 0;
    for (std::size_t w = 0; w < edges.size(); ++w) {
      const auto [start, end] = edges[w];
      a.words.push_back({t.words[w].text, 0});
      if (start > at) a.segments.push_back({SpeechSegmentKind::silence, Phone::SIL, at, start});
      const auto& v = entries[w].variants.front();
      const auto n = static_cast<std::int64_t>(v.size());
      for (std::int64_t k = 0; k < n; ++k)
        a.segments.push_back({SpeechSegmentKind::phone, v[static_cast<std::size_t>(k)], start + (end - start) * k / n,
                              start + (end - start) * (k + 1) / n, static_cast<int>(w), scores[w]});
      at = end;
    }
    if (at < samples) a.segments.push_back({SpeechSegmentKind::silence, Phone::SIL, at, samples});
  }
  for (auto& w : a.words) w.byte_offset = 0;
  finish_words(a);
  return a;
}

}  // namespace fapcast
