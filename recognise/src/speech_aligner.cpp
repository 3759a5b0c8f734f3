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
#include "pauses.hpp"
#include "weak_forms.hpp"
#include "fapcast/recognise/resample.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/frontend/espeak_language.hpp"
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

// The phone a phone is decoded as: the acoustic models have CMUdict's phones, whose schwa is AH.
Phone acoustic_phone(Phone p) { return p == Phone::AX ? Phone::AH : p; }

// The phones a grammar may name (all but SIL): a schwa keeps its name, spoken as AH.
std::vector<Phone> phone_set() {
  std::vector<Phone> out;
  for (std::size_t i = 0; i < kPhoneCount; ++i)
    if (static_cast<Phone>(i) != Phone::SIL) out.push_back(static_cast<Phone>(i));
  return out;
}

std::string tagged(char kind, Phone p, std::size_t word) {
  std::string s(1, kind);
  s.append(arpabet(p));
  s.push_back('@');
  s.push_back(static_cast<char>('0' + word % kTags));
  return s;
}

std::vector<std::pair<std::string, std::string>> phone_words() {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t k = 0; k < kTags; ++k)
    for (Phone p : phone_set())
      for (char kind : {'~', '#'}) out.emplace_back(tagged(kind, p, k), std::string(arpabet(acoustic_phone(p))));
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
  for (Phone p : phones) {
    if (!s.empty()) s.push_back(' ');
    s.append(arpabet(acoustic_phone(p)));
  }
  return s;
}

// True when word i ends the transcript or a punctuation mark follows it before the next word.
bool phrase_final(const Transcript& t, std::size_t i) {
  if (i + 1 == t.words.size()) return true;
  const std::size_t end = t.words[i].byte_offset + t.words[i].text.size();
  const std::string_view between = std::string_view(t.text).substr(end, t.words[i + 1].byte_offset - end);
  return between.find_first_of(".,;:!?") != std::string_view::npos;
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

// espeak-ng's phones (SIL left out) of each word of `t`, reading the whole transcript in
// `language`: a word's phones are those of the words espeak-ng reports inside its bytes; empty
// for a word it says nothing for.
std::vector<std::vector<Phone>> spoken_words(const Transcript& t, const std::string& language) {
  SpeakOptions options;
  options.language = language;
  const Speech spoken = speak(t.text, options);
  std::vector<std::vector<Phone>> out(t.words.size());
  for (std::size_t p = 0; p < spoken.phones.size(); ++p) {
    const int wi = spoken.events[p].word;
    if (wi < 0 || spoken.phones[p].phone == Phone::SIL) continue;
    const auto& sw = spoken.words[static_cast<std::size_t>(wi)];
    // the transcript word starting last at or before it (words are in byte order)
    const auto after = std::upper_bound(t.words.begin(), t.words.end(), sw.byte_offset,
                                        [](std::size_t b, const TranscriptWord& w) { return b < w.byte_offset; });
    if (after == t.words.begin()) continue;
    const auto& w = *(after - 1);
    if (sw.byte_offset < w.byte_offset + w.text.size())
      out[static_cast<std::size_t>(after - 1 - t.words.begin())].push_back(spoken.phones[p].phone);
  }
  return out;
}

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

  // Dictionary entries of every word, their schwas named by espeak-ng's reading of the transcript
  // (en-us); words the dictionary lacks get that reading, added to both decoders under their key.
  // With settings.weak_forms, each function word also gets its weak forms, and with
  // settings.language espeak-ng's reading of the transcript in that language (in context: its
  // weak forms, linking r), each as one more variant where it sounds unlike those, under the key
  // "word(PH_PH_...)".
  std::vector<WordEntry> entries(const Transcript& t) {
    Decoder& d = phone_decoder();
    std::vector<WordEntry> out(t.words.size());
    std::optional<std::vector<std::vector<Phone>>> us;
    std::vector<std::pair<std::string, std::string>> added;
    for (std::size_t i = 0; i < t.words.size(); ++i) {
      const auto& w = t.words[i];
      std::vector<std::string> prons = d.pronunciations(w.key);
      for (std::size_t k = 0; k < prons.size(); ++k) {
        out[i].keys.push_back(k == 0 ? w.key : w.key + "(" + std::to_string(k + 1) + ")");
        out[i].variants.push_back(parse_pronunciation(prons[k]));
      }
      if (!prons.empty()) continue;
      if (!us) us = spoken_words(t, std::string(kDefaultLanguage));
      const std::vector<Phone>& ph = (*us)[i];
      if (ph.empty())
        throw InputError({"transcript", std::nullopt, w.byte_offset}, "no-pronunciation",
                         "espeak-ng says nothing for '" + w.text + "'");
      out[i].keys.push_back(w.key);
      out[i].variants.push_back(ph);
      added.emplace_back(w.key, pronunciation_string(ph));
    }
    if (!added.empty()) d.add_words(added);  // the base words first: a "word(...)" key needs its word
    // one more variant of word i, where it differs from those it has
    std::vector<std::pair<std::string, std::string>> variants;
    // The variant of word i that sounds as `ph` does (the schwa is decoded as AH), if any.
    const auto same_sound = [&](std::size_t i, const std::vector<Phone>& ph) {
      auto& v = out[i].variants;
      return std::find_if(v.begin(), v.end(), [&](const std::vector<Phone>& x) {
        return std::ranges::equal(x, ph, {}, acoustic_phone, acoustic_phone);
      });
    };
    // The dictionary has no stress, so its schwa (CMUdict AH0) is AH: where a reading of the word
    // has the variant's consonants in the same places, the AH it reads as a schwa is named AX.
    const auto name_schwas = [&](std::size_t i, const std::vector<Phone>& ph) {
      for (auto& v : out[i].variants) {
        const bool aligned = v.size() == ph.size() && std::ranges::equal(v, ph, [](Phone a, Phone b) {
          return acoustic_phone(a) == acoustic_phone(b) || (is_vowel(a) && is_vowel(b));
        });
        if (!aligned) continue;
        for (std::size_t k = 0; k < v.size(); ++k)
          if (v[k] == Phone::AH && ph[k] == Phone::AX) v[k] = Phone::AX;
      }
    };
    const auto add_variant = [&](std::size_t i, const std::vector<Phone>& ph) {
      auto& e = out[i];
      if (ph.empty() || same_sound(i, ph) != e.variants.end()) return;
      std::string key = t.words[i].key + "(" + pronunciation_string(ph) + ")";
      std::replace(key.begin(), key.end(), ' ', '_');
      e.keys.push_back(key);
      e.variants.push_back(ph);
      // a word twice in the transcript: its key once
      if (std::none_of(variants.begin(), variants.end(), [&](const auto& v) { return v.first == key; }))
        variants.emplace_back(key, pronunciation_string(ph));
    };
    if (!us) us = spoken_words(t, std::string(kDefaultLanguage));
    for (std::size_t i = 0; i < t.words.size(); ++i) name_schwas(i, (*us)[i]);
    if (settings.weak_forms)
      for (std::size_t i = 0; i < t.words.size(); ++i) {
        const bool before_vowel =
            i + 1 < t.words.size() && std::any_of(out[i + 1].variants.begin(), out[i + 1].variants.end(),
                                                  [](const auto& v) { return !v.empty() && is_vowel(v.front()); });
        // A function word takes its weak form inside a phrase and its strong form at the end of
        // one (Roach 2009, ch. 12): inside, the dictionary's variant that sounds as the weak
        // form does is named as the weak form (its AH a schwa).
        for (std::string_view form : weak_forms(t.words[i].key, before_vowel)) {
          const std::vector<Phone> ph = parse_pronunciation(std::string(form));
          const auto v = same_sound(i, ph);
          if (v == out[i].variants.end()) add_variant(i, ph);
          else if (!phrase_final(t, i)) *v = ph;
        }
      }
    if (!settings.language.empty()) {
      const std::vector<std::vector<Phone>> read = spoken_words(t, settings.language);
      for (std::size_t i = 0; i < t.words.size(); ++i) {
        name_schwas(i, read[i]);
        add_variant(i, read[i]);
      }
    }
    if (!variants.empty()) d.add_words(variants);
    if (words) {
      if (!added.empty()) words->add_words(added);
      if (!variants.empty()) words->add_words(variants);
    }
    return out;
  }
};

namespace {

// The phone grammar over words [first, last): word i's variants run in parallel from boundary
// state i - first to i - first + 1; pauses (silence, noise) may repeat at every boundary. With
// `garbage`, each word may instead be a loop of garbage phones (or nothing: a word the recording
// leaves out). With `open_end`, the path may end after any word (a piece of a long recording).
Grammar phone_grammar(const std::vector<WordEntry>& entries, std::size_t first, std::size_t last, bool garbage,
                      bool open_end = false) {
  Grammar g;
  const int n = static_cast<int>(last - first);
  g.start = 0;
  g.final = n;
  int next = n + 1;
  for (int i = 0; i < n; ++i) {
    const std::size_t word = first + static_cast<std::size_t>(i);
    const double p = 1.0 / static_cast<double>(entries[word].variants.size());
    for (const auto& v : entries[word].variants) {
      int from = i;
      for (std::size_t k = 0; k < v.size(); ++k) {
        const int to = k + 1 == v.size() ? i + 1 : next++;
        g.arcs.push_back({from, to, tagged('~', v[k], word), k == 0 ? p : 1.0});
        from = to;
      }
    }
    if (garbage) {
      const int loop = next++;
      g.arcs.push_back({i, loop, "", kGarbageEnter});
      for (Phone ph : phone_set())
        if (acoustic_phone(ph) == ph) g.arcs.push_back({loop, loop, tagged('#', ph, word), kGarbagePhone});
      g.arcs.push_back({loop, i + 1, "", 1.0});
      // the recording stops before word i (at 0: has none of them): one null arc to the end, not a chain of skipped
      // words (each skip costs kGarbageEnter, so a chain falls out of the beam)
      g.arcs.push_back({i, n, "", kGarbageEnter});
    }
  }
  if (open_end && !garbage)
    for (int i = 1; i < n; ++i) g.arcs.push_back({i, n, "", 1.0});
  g.states = next;
  for (int i = 0; i <= n; ++i) g.pause_states.push_back(i);
  return g;
}
Grammar phone_grammar(const std::vector<WordEntry>& entries, bool garbage) {
  return phone_grammar(entries, 0, entries.size(), garbage);
}

// The word grammar: words [first, last) as whole dictionary entries (cross-word triphones).
Grammar word_grammar(const std::vector<WordEntry>& entries, std::size_t first, std::size_t last) {
  Grammar g;
  const int n = static_cast<int>(last - first);
  g.states = n + 1;
  g.final = n;
  for (int i = 0; i < n; ++i) {
    const auto& keys = entries[first + static_cast<std::size_t>(i)].keys;
    for (const auto& key : keys) g.arcs.push_back({i, i + 1, key, 1.0 / static_cast<double>(keys.size())});
  }
  for (int i = 0; i <= n; ++i) g.pause_states.push_back(i);
  return g;
}

// Reads a path decoded from the 16 kHz samples starting at `offset16` (a piece of the
// recording), onto the recording's timeline clamped to [begin, end) (its samples at `rate`).
struct PathReader {
  const Decoder& decoder;
  std::int64_t rate;
  std::int64_t samples;
  std::int64_t offset16 = 0;
  std::int64_t begin = 0;
  std::int64_t end = samples;

  std::int64_t to_sample(int frame) const {
    const std::int64_t s16 = decoder.frame_start_sample(frame) + offset16;
    return std::clamp<std::int64_t>((s16 * rate + kDecoderSampleRateHz / 2) / kDecoderSampleRateHz, begin, end);
  }

  // Segments from a phone-grammar path whose first word is transcript word `first`; `words`
  // gets one entry per transcript word.
  SpeechAlignment read(const std::vector<DecodedSegment>& path, const Transcript& t, std::size_t first = 0) const {
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
        std::size_t w = started ? word : first;
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
      a.segments.front().start_sample = begin;
      a.segments.back().end_sample = end;
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
// `edges` are those of words first, first + 1, ...
void snap_word_edges(SpeechAlignment& a, const std::vector<std::pair<std::int64_t, std::int64_t>>& edges,
                     std::int64_t min_gap, std::size_t first_word = 0) {
  auto& seg = a.segments;
  for (std::size_t w = 0; w < edges.size(); ++w) {
    int first = -1, last = -1;
    for (std::size_t i = 0; i < seg.size(); ++i)
      if (seg[i].word == static_cast<int>(first_word + w)) {
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

// A piece of a long recording: 16 kHz samples [begin16, end16) and the transcript words
// [first, last) its path went through.
struct Piece {
  std::int64_t begin16 = 0;
  std::int64_t end16 = 0;
  std::size_t first = 0;
  std::size_t last = 0;
};

// Pieces of kMinPieceSeconds to about kMaxPieceSeconds, cut where the recording pauses; a
// recording under twice the first is aligned in one piece (spec/recognise.md, "Long recordings").
constexpr std::int64_t kMinPieceSeconds = 4;
constexpr std::int64_t kMaxPieceSeconds = 10;

struct PiecewiseAlignment {
  SpeechAlignment alignment;
  std::vector<Piece> pieces;
};

// `s16` (the recording at 16 kHz) aligned piece by piece: cut at pauses (pauses.hpp), each piece
// decoded over the next transcript words with an open end (its path may stop after any word;
// 1.2 times the words the mean speaking rate expects, plus 6; twice as many again while the path
// uses every word offered), the next piece starting at the word after its last; the last piece
// must end the transcript. A piece with no path is joined to the next once; nullopt when the
// recording has no cut or a joined piece still finds no path: the caller aligns it whole.
std::optional<PiecewiseAlignment> align_in_pieces(Decoder& pd, bool word_edges_pass, std::span<const std::int16_t> s16,
                                                  const std::vector<WordEntry>& entries, const Transcript& t,
                                                  std::int64_t rate, std::int64_t samples) {
  const auto length = static_cast<std::int64_t>(s16.size());
  if (length < 2 * kMinPieceSeconds * kDecoderSampleRateHz || entries.empty()) return std::nullopt;
  std::vector<std::int64_t> cuts = cut_points(find_pauses(s16), length, kMinPieceSeconds * kDecoderSampleRateHz,
                                              kMaxPieceSeconds * kDecoderSampleRateHz);
  if (cuts.empty()) return std::nullopt;
  cuts.push_back(length);
  const auto to_rate = [&](std::int64_t s) {
    return std::clamp<std::int64_t>((s * rate + kDecoderSampleRateHz / 2) / kDecoderSampleRateHz, 0, samples);
  };
  const std::size_t n = entries.size();
  const double words_per_sample = static_cast<double>(n) / static_cast<double>(length);
  // The path through piece [begin, end) from word w0 (captured by reference below); w1 gets the
  // word after its last.
  std::size_t w0 = 0;
  auto piece_path = [&](std::int64_t begin, std::int64_t end, bool last_piece, std::size_t& w1) -> std::optional<SpeechAlignment> {
    const auto piece = s16.subspan(static_cast<std::size_t>(begin), static_cast<std::size_t>(end - begin));
    const PathReader reader{pd, rate, samples, begin, begin == 0 ? 0 : to_rate(begin), last_piece ? samples : to_rate(end)};
    std::size_t offered = last_piece ? n - w0
                                     : static_cast<std::size_t>(1.2 * words_per_sample * static_cast<double>(end - begin)) + 6;
    while (true) {
      w1 = std::min(n, w0 + offered);
      const auto path = pd.decode(phone_grammar(entries, w0, w1, false, !last_piece), piece);
      if (!path) return std::nullopt;
      SpeechAlignment p = reader.read(*path, t, w0);
      int reached = -1;
      for (const auto& g : p.segments)
        if (g.kind == SpeechSegmentKind::phone) reached = std::max(reached, g.word);
      if (reached < static_cast<int>(w0)) return std::nullopt;
      const auto next = static_cast<std::size_t>(reached) + 1;
      if (last_piece || next < w1 || w1 == n) {
        w1 = next;
        return p;
      }
      offered *= 2;  // the path used every word offered: the piece may say more
    }
  };
  PiecewiseAlignment out;
  SpeechAlignment& a = out.alignment;
  a.sample_rate = SampleRate{rate};
  a.samples = samples;
  std::int64_t begin = 0;
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    if (w0 >= n) return std::nullopt;  // the words ran out before the recording
    // A piece with no path is joined to the next one once (a cut the transcript split badly).
    std::optional<SpeechAlignment> found;
    std::size_t w1 = 0;
    for (bool joined = false; !found; joined = true) {
      if (joined) {
        if (k + 1 == cuts.size()) return std::nullopt;
        ++k;
      }
      const bool last_piece = k + 1 == cuts.size();
      found = piece_path(begin, cuts[k], last_piece, w1);
      if (!found && joined) return std::nullopt;
    }
    const std::int64_t end = cuts[k];
    SpeechAlignment& p = *found;
    const auto piece = s16.subspan(static_cast<std::size_t>(begin), static_cast<std::size_t>(end - begin));
    const PathReader reader{pd, rate, samples, begin, k == 0 ? 0 : to_rate(begin), k + 1 == cuts.size() ? samples : to_rate(end)};
    if (word_edges_pass)
      if (const auto wpath = pd.decode(word_grammar(entries, w0, w1), piece)) {
        const auto edges = word_edges(*wpath, reader);
        if (edges.size() == w1 - w0) snap_word_edges(p, edges, rate / 200, w0);
      }
    for (const auto& g : p.segments) {
      if (!a.segments.empty() && g.kind != SpeechSegmentKind::phone && a.segments.back().kind == g.kind &&
          a.segments.back().word == g.word) {
        a.segments.back().end_sample = g.end_sample;  // the pause a cut falls in, joined again
        continue;
      }
      a.segments.push_back(g);
    }
    out.pieces.push_back({begin, end, w0, w1});
    w0 = w1;
    begin = end;
  }
  for (const auto& w : t.words) a.words.push_back({w.text, w.byte_offset});
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
  if (!settings.language.empty() && !espeak_language_installed(settings.language))
      throw std::invalid_argument("SpeechAligner: unknown language '" + settings.language +
                                  "' (`espeak-ng --voices` lists the installed ones)");
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

  // Where a recording (or the piece of it from 16 kHz sample begin16, through words [first,
  // last)) diverges from its transcript: the garbage loop at 100 fps.
  const auto length16 = static_cast<std::int64_t>(s16.samples.size());
  auto diagnose = [&](const Piece& piece) -> std::optional<SpeechAlignment> {
    Decoder& wd = impl_->word_decoder();
    const auto to_rate = [&](std::int64_t s) { return std::clamp<std::int64_t>((s * rate + kDecoderSampleRateHz / 2) / kDecoderSampleRateHz, 0, samples); };
    const PathReader wr{wd, rate, samples, piece.begin16, piece.begin16 == 0 ? 0 : to_rate(piece.begin16),
                        piece.end16 == length16 ? samples : to_rate(piece.end16)};
    const auto path = wd.decode(phone_grammar(entries, piece.first, piece.last, true),
                                std::span<const std::int16_t>(s16.samples).subspan(static_cast<std::size_t>(piece.begin16),
                                                                                   static_cast<std::size_t>(piece.end16 - piece.begin16)));
    if (!path) throw InputError({source, std::nullopt, std::nullopt}, "no-speech", "no path through the transcript fits the recording, even with words left out (another recording's text, silence or noise?)");
    SpeechAlignment d = wr.read(*path, transcript, piece.first);
    std::vector<bool> matched(transcript.words.size(), false), garbage(transcript.words.size(), false);
    for (const auto& g : d.segments) {
      if (g.word < 0) continue;
      (g.kind == SpeechSegmentKind::phone ? matched : garbage)[static_cast<std::size_t>(g.word)] = true;
    }
    if (std::none_of(matched.begin() + static_cast<std::ptrdiff_t>(piece.first), matched.begin() + static_cast<std::ptrdiff_t>(piece.last), [](bool m) { return m; }))
      throw InputError({source, std::nullopt, std::nullopt}, "no-speech", "no word of the transcript was found in the recording (silence, noise, another recording?)");
    for (std::size_t w = piece.first; w < piece.last; ++w) {
      if (matched[w] && !garbage[w]) continue;
      std::int64_t at = wr.begin;  // where the recording leaves the transcript: the garbage, or the end of the last word found
      for (const auto& g : d.segments)
        if (g.word == static_cast<int>(w) && g.kind == SpeechSegmentKind::unmatched) { at = g.start_sample; break; }
        else if (g.word >= static_cast<int>(piece.first) && g.word < static_cast<int>(w)) at = g.end_sample;
      const auto& tw = transcript.words[w];
      throw InputError({source, std::nullopt, std::nullopt}, "transcript-mismatch",
                       seconds(at, rate) + ": the recording diverges from the transcript at word " + std::to_string(w + 1) +
                           " '" + tw.text + "' (byte " + std::to_string(tw.byte_offset) + ")" +
                           (matched[w] ? "" : ": not found in the recording"));
    }
    finish_words(d);
    return d;
  };
  const Piece whole{0, length16, 0, entries.size()};
  const auto low = [](const SpeechAlignment& x) {
    return std::any_of(x.words.begin(), x.words.end(), [](const SpeechWord& w) { return w.low_confidence; });
  };

  SpeechAlignment a;
  std::optional<PiecewiseAlignment> pieces;
  if (impl_->settings.in_pieces)
    pieces = align_in_pieces(pd, impl_->settings.word_edges, s16.samples, entries, transcript, rate, samples);
  if (pieces) {
    a = std::move(pieces->alignment);
    finish_words(a);
    for (const Piece& piece : pieces->pieces)  // each piece with a low-confidence word diagnosed alone
      for (std::size_t w = piece.first; w < piece.last; ++w)
        if (a.words[w].low_confidence) {
          diagnose(piece);
          break;
        }
  } else if (const auto path = pd.decode(phone_grammar(entries, false), s16.samples)) {
    a = reader.read(*path, transcript);
    if (impl_->settings.word_edges)
      if (const auto wpath = pd.decode(word_grammar(entries, 0, entries.size()), s16.samples)) {
        const auto edges = word_edges(*wpath, reader);
        if (edges.size() == transcript.words.size()) snap_word_edges(a, edges, rate / 200);
      }
    finish_words(a);
    if (low(a)) diagnose(whole);
  } else {
    a = *diagnose(whole);  // throws, or aligns at 100 fps when every word is there; then checked as any alignment
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
  std::optional<PiecewiseAlignment> pieces;
  if (impl_->settings.in_pieces) pieces = align_in_pieces(pd, false, s16.samples, entries, t, rate, samples);
  if (pieces) {
    a = std::move(pieces->alignment);
    snap_word_edges(a, edges, rate / 200);
  } else if (const auto path = pd.decode(phone_grammar(entries, false), s16.samples)) {
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
