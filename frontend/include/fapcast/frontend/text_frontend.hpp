#pragma once
// The text front-end: text in any espeak-ng language (or SSML) in, speech audio and a phone
// timeline out, from espeak-ng through its C API. Positions are samples of the returned audio, taken from the
// events' exact `sample` field (their millisecond field is rounded).
//
// Segments: espeak-ng's phoneme events mark where each phone's sound starts; for a stop that
// is its release. The lips (or tongue) close earlier, in the near-silence before the burst, so
// for phones with a closure (stops, affricates, /m/; has_closure()) the segment starts at the
// closure found in the audio (find_closure). The timeline is contiguous: each phone ends where
// the next begins.
//
// Phones: en-us (the default) maps espeak-ng's mnemonics through phone_from_espeak; every other
// language runs espeak-ng in IPA mode and maps each phoneme's IPA through its features
// (ipa_features.hpp). Texts longer than kChunkBytes are synthesised sentence by sentence in
// chunks of at most kChunkBytes (no length limit; espeak-ng's buffers stay bounded).
//
// Input rules (spec/phones.md, "Text front-end"):
//  - valid UTF-8, any length; no control characters except TAB, LF, CR;
//    anything else throws InputError (input_error.hpp) naming the byte offset;
//  - empty or whitespace-only text gives empty speech (no samples, no phones) without espeak;
//  - text espeak-ng says nothing for (e.g. "...") gives a short stretch of silence, phones all SIL;
//  - emoji and non-Latin characters are read out by espeak-ng by name ("grinning face").
// espeak-ng is not thread-safe: calls are serialised by a process-wide mutex.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/audio.hpp"
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/phonetics/timed_phone.hpp"

namespace fapcast {

// Texts up to this size go to espeak-ng in one call; longer ones in chunks of whole sentences of
// at most this size (a sentence longer than this is cut at a space, else at a code point).
inline constexpr std::size_t kChunkBytes = 4 * 1024;

// The default language: its phones come from the hand-checked mnemonic map.
inline constexpr std::string_view kDefaultLanguage = "en-us";

inline constexpr int kNoWord = -1;

// What espeak-ng said of a phone, beside its TimedPhone.
struct PhoneEvent {
  std::int64_t event_sample;    // where espeak-ng's phoneme event put the phone
  std::int64_t release_sample;  // end of the closure's quiet stretch; = the phone's start for other phones
  int word;                     // index into Speech::words, kNoWord for silence
  std::string espeak;           // the espeak-ng mnemonic reported (IPA for languages other than en-us)
  friend bool operator==(const PhoneEvent&, const PhoneEvent&) = default;
};

struct TimedWord {
  std::string text;             // the word as written in the input (UTF-8)
  std::size_t byte_offset;      // where it starts in the input
  std::int64_t start_sample;    // first phone's start
  std::int64_t end_sample;      // last phone's end
  friend bool operator==(const TimedWord&, const TimedWord&) = default;
};

struct Speech {
  Audio audio;              // espeak-ng's own rate (22050 Hz for its voices), mono int16
  std::vector<TimedPhone> phones;
  std::vector<PhoneEvent> events;  // one per phone
  std::vector<TimedWord> words;
};

struct SpeakOptions {
  // Treat text inside [[ ]] as espeak-ng phoneme mnemonics (espeakPHONEMES), e.g. nonsense
  // syllables of the recording script. Off by default: user text is text.
  bool phoneme_input = false;
  // Speaking rate relative to espeak-ng's default of 175 words per minute (1.1 = 10 % faster);
  // the reference talker varies it per utterance. Clamped to espeak-ng's 80..450 wpm.
  double rate_factor = 1.0;
  // espeak-ng language (voice) code as `espeak-ng --voices` lists it: "ru", "de", "cmn", "en-gb".
  std::string language = std::string(kDefaultLanguage);
  // espeak-ng voice variant (`espeak-ng --voices=variant`, the file name under !v/: "f2",
  // "klatt", "Alex"); empty: the language's own voice.
  std::string variant{};
  // The text is SSML (espeakSSML): espeak-ng parses the markup; tags are not spoken. SSML is
  // never split into chunks.
  bool ssml = false;
  // What input errors name as the text's source ("text: byte 12: ..."): a file name, "<stdin>".
  std::string source = "text";
};

// An installed espeak-ng language.
struct EspeakLanguage {
  std::string code;  // "ru", "en-us"
  std::string name;  // "Russian", "English (America)"
};
// Every language the installed espeak-ng lists (its voices), in its order.
std::vector<EspeakLanguage> espeak_languages();
// Every voice variant the installed espeak-ng lists ("adam", "f2", ...).
std::vector<std::string> espeak_variants();

// Byte offsets where `text` is cut into chunks of at most `max_bytes` (the first is 0, the
// last < text.size(); empty text gives none): after the white space that follows a sentence end
// (. ! ? and their CJK forms, or a line break), packed greedily; a longer sentence is cut after
// the last space that fits, else at the last code point boundary that fits.
std::vector<std::size_t> chunk_offsets(std::string_view text, std::size_t max_bytes);

// Synthesises `text` (UTF-8) with espeak-ng and segments it into phones and words.
// Throws InputError for text that breaks the input rules above, std::invalid_argument for an
// unknown language or variant ("espeak-ng: unknown language 'xx'") and for a phoneme whose IPA
// has an unknown symbol (naming phoneme and language), std::runtime_error if espeak-ng fails
// (e.g. its data is missing). espeak-ng 1.51 carries synthesiser state (its pitch flutter's
// phase) from call to call: the same text may come out a few samples longer or shorter after
// other speech in the process. What must be reproducible is spoken from a fresh process
// (spec/voice.md, "The default voice").
Speech speak(std::string_view text, const SpeakOptions& options = {});

// The same text as speak() gives, chunk by chunk (kChunkBytes), for callers that keep only one
// chunk at a time: `sink` gets each chunk's speech in order, its samples and phones counted from
// the chunk's own start, its words' byte offsets into the whole text. A text of at most
// kChunkBytes (or SSML) is one chunk. Throws as speak() does (input errors before any chunk).
// The samples a sink leaves in the chunk (it reads them without moving them out) are the next
// chunk's buffer: its memory is reused, not allocated and faulted in again.
void speak_chunks(std::string_view text, const SpeakOptions& options, const std::function<void(Speech&&)>& sink);

// Appends a chunk of speak_chunks to `all` as speak() does, but its timing only: phones, events
// and words shifted by `offset` (the samples of speech before the chunk), a silence that ends
// `all` and starts the chunk made one; the chunk's audio is left to the caller (`say` writes it
// to the WAV as it comes, so a long text's speech is never held whole). Returns false, and
// appends nothing, for a chunk without phones (speak() drops its audio too).
bool append_timing(Speech& all, Speech&& part, std::int64_t offset);

// Checks the input rules; throws InputError "text: byte N: <rule>: <detail>" on the first
// violation. Returns the byte offset of every code point (for espeak's character positions).
std::vector<std::size_t> validate_text(std::string_view text);

// A closure found in the audio: where the energy drops (onset) and where it returns (release).
struct Closure {
  std::int64_t onset_sample;
  std::int64_t release_sample;
  friend bool operator==(const Closure&, const Closure&) = default;
};

// Finds the closure of a phone whose event is at `event_sample`, searching back to
// `region_begin` (the previous phone's start) and forward to `region_end` (its own end): the
// near-silent stretch (short-time RMS below a fifth of the previous phone's peak, 10 ms
// windows every 2.5 ms) that starts at most 10 ms before and at most 40 ms after the event.
// With no quiet stretch the closure is the event itself. After silence (nothing to drop from)
// the onset is 50 ms before the event, bounded by region_begin.
Closure find_closure(std::span<const std::int16_t> samples, SampleRate sample_rate,
                     std::int64_t region_begin, std::int64_t event_sample, std::int64_t region_end);

}  // namespace fapcast
