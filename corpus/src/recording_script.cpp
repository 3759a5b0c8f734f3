#include "fapcast/corpus/recording_script.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "fapcast/math/greedy_cover.hpp"
#include "fapcast/phonetics/phone_map.hpp"

namespace fapcast {

namespace {

constexpr auto kSilenceClass = static_cast<std::size_t>(VisemeClass::kSilence);

std::string syllable_key(const Syllable& s) {
  std::string key;
  for (Phone p : s.phones) key += std::string(arpabet(p)) + " ";
  return key;
}

std::string arpabet_spelling(const std::vector<Syllable>& syllables) {
  std::string out;
  for (std::size_t i = 0; i < syllables.size(); ++i) {
    if (i > 0) out += " . ";
    for (std::size_t k = 0; k < syllables[i].phones.size(); ++k) {
      const Phone p = syllables[i].phones[k];
      if (k > 0) out += ' ';
      out += arpabet(p);
      if (is_vowel(p)) out += static_cast<char>('0' + static_cast<int>(syllables[i].stress));
    }
  }
  return out;
}

}  // namespace

std::vector<Phone> phones_of(const std::vector<Syllable>& syllables) {
  std::vector<Phone> phones;
  for (const Syllable& s : syllables) phones.insert(phones.end(), s.phones.begin(), s.phones.end());
  return phones;
}

std::string diviseme_name(std::uint32_t id) {
  // Inverse of diviseme_id.
  const std::size_t full = id >= kSilenceClass * kVisemeClassCount + kSilenceClass ? id + 1 : id;
  return std::string(viseme_class_name(static_cast<VisemeClass>(full / kVisemeClassCount))) + ">" +
         std::string(viseme_class_name(static_cast<VisemeClass>(full % kVisemeClassCount)));
}

std::vector<std::vector<Phone>> nonsense_candidates() {
  const std::vector<Phone> reps = nonsense_alphabet();
  std::vector<std::vector<Phone>> out;
  for (Phone a : reps) {
    for (Phone b : reps) {
      for (Phone c : reps) {
        if (!is_vowel(a) && !is_vowel(b) && !is_vowel(c)) continue;
        if (a == Phone::R && !is_vowel(b)) continue;  // no English onset: espeak-ng drops the r
        out.push_back({a, b, c});
      }
    }
  }
  return out;
}

std::uint32_t diviseme_id(VisemeClass a, VisemeClass b) {
  const std::size_t full = static_cast<std::size_t>(a) * kVisemeClassCount + static_cast<std::size_t>(b);
  constexpr std::size_t kSilSil = kSilenceClass * kVisemeClassCount + kSilenceClass;
  if (full == kSilSil) throw std::invalid_argument("diviseme_id: silence>silence is not a diviseme");
  return static_cast<std::uint32_t>(full > kSilSil ? full - 1 : full);
}

std::vector<std::uint32_t> divisemes_of(const std::vector<Phone>& phones) {
  std::vector<std::uint32_t> ids;
  VisemeClass previous = VisemeClass::kSilence;
  for (Phone p : phones) {
    const VisemeClass v = search_viseme(p);
    if (!(previous == VisemeClass::kSilence && v == VisemeClass::kSilence)) ids.push_back(diviseme_id(previous, v));
    previous = v;
  }
  if (previous != VisemeClass::kSilence) ids.push_back(diviseme_id(previous, VisemeClass::kSilence));
  return ids;
}

RecordingScript build_recording_script(const std::vector<WordCount>& counts,
                                       const std::vector<LexiconEntry>& lexicon,
                                       const ScriptOptions& options) {
  std::unordered_map<std::string, const LexiconEntry*> pronunciation;
  for (const LexiconEntry& e : lexicon) pronunciation.emplace(e.word, &e);  // first entry wins

  // Candidate words (most frequent first) and their syllables.
  struct Candidate { const WordCount* word; const LexiconEntry* entry; };
  std::vector<Candidate> candidates;
  for (const WordCount& wc : counts) {
    if (candidates.size() >= options.candidate_words) break;
    const auto it = pronunciation.find(wc.word);
    if (it != pronunciation.end()) candidates.push_back({&wc, it->second});
  }
  std::map<std::string, std::uint32_t> syllable_ids;  // ordered: deterministic ids
  for (const Candidate& c : candidates) {
    for (const Syllable& s : c.entry->syllables) syllable_ids.emplace(syllable_key(s), 0);
  }
  std::uint32_t next = 0;
  for (auto& [key, id] : syllable_ids) id = next++;
  std::vector<double> syllable_weight(syllable_ids.size(), 0.0);
  std::vector<std::vector<std::uint32_t>> word_syllables;
  for (const Candidate& c : candidates) {
    std::vector<std::uint32_t> ids;
    for (const Syllable& s : c.entry->syllables) {
      ids.push_back(syllable_ids.at(syllable_key(s)));
      syllable_weight[ids.back()] += static_cast<double>(c.word->count);
    }
    word_syllables.push_back(std::move(ids));
  }

  RecordingScript script;
  std::vector<bool> syllable_covered(syllable_weight.size(), false);
  std::vector<bool> diviseme_covered(kDivisemeCount, false);
  const auto add_word = [&](std::size_t c, ScriptSection section, double gain) {
    for (std::uint32_t id : word_syllables[c]) syllable_covered[id] = true;
    for (std::uint32_t d : divisemes_of(phones_of(candidates[c].entry->syllables))) diviseme_covered[d] = true;
    script.items.push_back({section, candidates[c].word->word, candidates[c].entry->syllables, "", gain});
  };
  const std::size_t common = std::min(options.common_words, candidates.size());
  for (std::size_t c = 0; c < common; ++c) add_word(c, ScriptSection::kCommonWord, 0.0);
  // Words already taken offer nothing new: their syllables are covered.
  for (const GreedyPick& pick : greedy_cover(word_syllables, syllable_weight, syllable_covered, options.syllable_words)) {
    add_word(pick.candidate, ScriptSection::kSyllableWord, pick.gain);
  }
  script.coverage.candidate_words = candidates.size();
  script.coverage.distinct_syllables = syllable_weight.size();
  double total = 0, covered = 0;
  for (std::size_t i = 0; i < syllable_weight.size(); ++i) {
    total += syllable_weight[i];
    if (syllable_covered[i]) { covered += syllable_weight[i]; ++script.coverage.covered_syllables; }
  }
  script.coverage.syllable_token_share = total > 0 ? covered / total : 0.0;
  script.coverage.divisemes_by_words = static_cast<std::size_t>(std::count(diviseme_covered.begin(), diviseme_covered.end(), true));

  // Nonsense syllables for the divisemes the words missed.
  const std::vector<std::vector<Phone>> nonsense = nonsense_candidates();
  std::vector<std::vector<std::uint32_t>> nonsense_units;
  for (const auto& n : nonsense) nonsense_units.push_back(divisemes_of(n));
  const std::vector<double> unit_weight(kDivisemeCount, 1.0);
  for (const GreedyPick& pick : greedy_cover(nonsense_units, unit_weight, diviseme_covered, nonsense.size())) {
    const std::vector<Phone>& phones = nonsense[pick.candidate];
    Syllable s{phones, Stress::kPrimary};
    script.items.push_back({ScriptSection::kNonsense, arpabet_spelling({s}), {s}, nonsense_espeak_phonemes(phones), pick.gain});
  }
  for (std::uint32_t d = 0; d < kDivisemeCount; ++d) {
    if (diviseme_covered[d]) ++script.coverage.divisemes_total_covered;
    else script.coverage.uncovered_divisemes.push_back(d);
  }
  return script;
}

std::vector<Phone> nonsense_alphabet() {
  std::vector<Phone> alphabet;
  for (std::size_t c = 0; c < kVisemeClassCount; ++c) {
    const auto v = static_cast<VisemeClass>(c);
    if (v == VisemeClass::kRhotic) alphabet.push_back(Phone::R);
    else if (c != kSilenceClass) alphabet.push_back(representative_phone(v));
  }
  return alphabet;
}

std::string nonsense_espeak_phonemes(const std::vector<Phone>& phones) {
  std::string espeak = "[[";
  bool stressed = false;
  for (std::size_t k = 0; k < phones.size(); ++k) {
    const Phone p = phones[k];
    if (is_vowel(p)) {
      espeak += stressed ? ',' : '\'';
      stressed = true;
    }
    if (p == Phone::IH) espeak += "I#";
    else if (p == Phone::AX && k + 1 < phones.size() && phones[k + 1] == Phone::R) espeak += "@2";
    else espeak += espeak_mnemonic(p);
  }
  return espeak + "]]";
}

std::string format_coverage(const ScriptCoverage& c) {
  char buf[512];
  std::string out;
  std::snprintf(buf, sizeof buf, "# candidate words in lexicon: %zu\n", c.candidate_words);
  out += buf;
  std::snprintf(buf, sizeof buf, "# syllables covered: %zu of %zu distinct (%.2f %% of syllable tokens)\n",
                c.covered_syllables, c.distinct_syllables, 100.0 * c.syllable_token_share);
  out += buf;
  std::snprintf(buf, sizeof buf, "# divisemes covered by words: %zu of %zu (%.2f %%)\n", c.divisemes_by_words,
                kDivisemeCount, 100.0 * double(c.divisemes_by_words) / double(kDivisemeCount));
  out += buf;
  std::snprintf(buf, sizeof buf, "# divisemes covered in total: %zu of %zu (%.2f %%)\n", c.divisemes_total_covered,
                kDivisemeCount, 100.0 * double(c.divisemes_total_covered) / double(kDivisemeCount));
  out += buf;
  out += "# uncovered divisemes:";
  if (c.uncovered_divisemes.empty()) out += " none";
  for (std::uint32_t d : c.uncovered_divisemes) out += " " + diviseme_name(d);
  out += "\n";
  return out;
}

std::string format_recording_script(const RecordingScript& script) {
  std::size_t counts[3] = {0, 0, 0};
  for (const ScriptItem& item : script.items) ++counts[static_cast<int>(item.section)];
  std::string out = "# fapcast recording script (Ma et al. 2006, section 3.2)\n";
  out += "# sections: common " + std::to_string(counts[0]) + ", syllable " + std::to_string(counts[1]) +
         ", nonsense " + std::to_string(counts[2]) + "\n";
  out += format_coverage(script.coverage);
  out += "# section\tnumber\ttext\tarpabet\tespeak\n";
  static constexpr const char* kNames[] = {"common", "syllable", "nonsense"};
  std::size_t number[3] = {0, 0, 0};
  for (const ScriptItem& item : script.items) {
    const int s = static_cast<int>(item.section);
    out += std::string(kNames[s]) + "\t" + std::to_string(++number[s]) + "\t" + item.text + "\t" +
           arpabet_spelling(item.syllables) + "\t" + item.espeak_phonemes + "\n";
  }
  return out;
}

}  // namespace fapcast
