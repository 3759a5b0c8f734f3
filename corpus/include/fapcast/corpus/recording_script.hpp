#pragma once
// The recording script of a visual-speech corpus (paper section 3.2): the most common words,
// words that cover the most frequent syllables, and nonsense syllables that cover every
// diviseme (ordered pair of search viseme classes, viseme.hpp), chosen by greedy coverage.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fapcast/corpus/syllabified_lexicon.hpp"
#include "fapcast/phonetics/viseme.hpp"

namespace fapcast {

struct ScriptOptions {
  std::size_t common_words = 100;       // most frequent words, taken as they come
  std::size_t syllable_words = 800;     // picked greedily for syllable coverage
  std::size_t candidate_words = 20000;  // most frequent words considered (and syllables counted over)
};

// Divisemes: ordered pairs (a, b) of search classes, except (silence, silence): 21 * 21 - 1.
inline constexpr std::size_t kDivisemeCount = kVisemeClassCount * kVisemeClassCount - 1;

// Dense id of the diviseme a -> b (not both silence), in [0, kDivisemeCount).
std::uint32_t diviseme_id(VisemeClass a, VisemeClass b);

// The phones of a pronunciation, syllable after syllable.
std::vector<Phone> phones_of(const std::vector<Syllable>& syllables);

// The divisemes of an utterance of `phones` spoken alone: silence, the phones, silence.
std::vector<std::uint32_t> divisemes_of(const std::vector<Phone>& phones);

// "open_front>bilabial": the classes of diviseme `id`, as spec/visemes.tsv names them.
std::string diviseme_name(std::uint32_t id);

// The nonsense items' alphabet, one phone per viseme class but silence: the class's
// representative_phone, except the rhotic class's, R. Nonsense items record the divisemes words
// miss, which for the rhotic class are the consonant between vowels ("for us" F AX R AH S), not
// the r-coloured vowel ER.
std::vector<Phone> nonsense_alphabet();

// The nonsense candidates: three letters of nonsense_alphabet() with at least one vowel (a
// pronounceable core), e.g. B AA D, each covering sil>a, a>b, b>c, c>sil; none starts with R
// before a consonant, an onset English lacks (espeak-ng drops the r).
std::vector<std::vector<Phone>> nonsense_candidates();

// espeak-ng phoneme input ("[[b'A:d]]") that espeak-ng en-us says as `phones`, one syllable
// stressed on its first vowel. Spelled so that its reading rules leave each phone as asked: a
// secondary stress before every later vowel (no two vowels read as a diphthong, no r linking
// them), IH as the reduced I# (a final I is read as the happy vowel i, and I before a vowel
// takes a glide), AX before R as @2 (@r is read as the r-coloured 3). espeak-ng still puts a
// glide (;, read as Y) between IY and a following vowel.
std::string nonsense_espeak_phonemes(const std::vector<Phone>& phones);

enum class ScriptSection { kCommonWord, kSyllableWord, kNonsense };

struct ScriptItem {
  ScriptSection section;
  std::string text;                 // the word, or the nonsense item's ARPAbet spelling
  std::vector<Syllable> syllables;  // its pronunciation (nonsense: one syllable)
  std::string espeak_phonemes;      // espeak-ng phoneme input ("[[b'A:d]]") for nonsense items
  double gain;                      // greedy gain when picked (syllable tokens or divisemes); 0 for common words
};

struct ScriptCoverage {
  std::size_t candidate_words = 0;        // candidates found in the lexicon
  std::size_t distinct_syllables = 0;     // over the candidate words
  std::size_t covered_syllables = 0;      // by the script's words
  double syllable_token_share = 0.0;      // frequency-weighted share of syllable tokens covered
  std::size_t divisemes_by_words = 0;
  std::size_t divisemes_total_covered = 0;
  std::vector<std::uint32_t> uncovered_divisemes;  // ids; empty when complete
};

struct RecordingScript {
  std::vector<ScriptItem> items;
  ScriptCoverage coverage;
};

// Builds the script from word counts (most frequent first) and a syllabified lexicon (the first
// entry of a word is its pronunciation). Words missing from the lexicon are skipped. Deterministic.
RecordingScript build_recording_script(const std::vector<WordCount>& counts,
                                       const std::vector<LexiconEntry>& lexicon,
                                       const ScriptOptions& options = {});

// The script as text: '#' header and coverage lines, then one TSV line per item:
// section, number, text, ARPAbet with stress and " . " between syllables, espeak input.
std::string format_recording_script(const RecordingScript& script);

// The coverage summary alone (what `fapcast corpus script` prints).
std::string format_coverage(const ScriptCoverage& coverage);

}  // namespace fapcast
