#pragma once
// Maps from the symbol sets fapcast meets into its ARPAbet phone set (phone.hpp): espeak-ng's
// phoneme mnemonics (en-us voice, as its phoneme events name them), IPA as `espeak-ng --ipa`
// writes it, and TIMIT/MOCHA labels. Each map is a constexpr table with one commented row per
// symbol; spec/phones.md lists them. Folding follows Lee & Hon (1989) where it applies:
// syllabic consonants become their consonant, r-coloured diphthongs their nucleus.
#include <array>
#include <string_view>
#include <utility>
#include <vector>

#include "fapcast/phonetics/phone.hpp"

namespace fapcast {

// espeak-ng en-us mnemonic -> phone. Every symbol seen in the phoneme events for the 74,000
// SUBTLEX-US words plus numbers and interjections (tests/phonetics/phone_test.cpp re-checks).
inline constexpr auto kEspeakMap = std::to_array<std::pair<std::string_view, Phone>>({
    {"a", Phone::AE},     // trap
    {"aa", Phone::AE},    // bath (en-us: same as trap)
    {"a#", Phone::AX},    // reduced a, IPA ɐ ("a pup"): a schwa
    {"A:", Phone::AA},    // palm
    {"A@", Phone::AA},    // start: ɑːɹ, the r-colouring is folded into the nucleus
    {"A~", Phone::AA},    // nasal vowel in French loans
    {"0", Phone::AA},     // lot (unrounded in en-us)
    {"aI", Phone::AY},    // price
    {"aI@", Phone::AY},   // fire (aɪə)
    {"aI3", Phone::AY},   // fire (aɪɚ)
    {"aU", Phone::AW},    // mouth
    {"@", Phone::AX},     // schwa (CMUdict AH0)
    {"@2", Phone::AX},    // schwa variant
    {"@5", Phone::AX},    // schwa variant (to)
    {"@-", Phone::AX},    // optional schwa
    {"@L", Phone::L},     // syllabic l (TIMIT el -> l)
    {"3", Phone::ER},     // letter: ɚ (CMUdict ER0)
    {"3:", Phone::ER},    // nurse: ɜː
    {"V", Phone::AH},     // strut
    {"E", Phone::EH},     // dress
    {"e", Phone::EH},     // e in loans
    {"e@", Phone::EH},    // square: ɛɹ
    {"eI", Phone::EY},    // face
    {"I", Phone::IH},     // kit
    {"I2", Phone::IH},    // unstressed kit
    {"I#", Phone::IH},    // reduced i, IPA ᵻ (TIMIT ix -> ih)
    {"i", Phone::IY},     // happy (final unstressed)
    {"i:", Phone::IY},    // fleece
    {"i@", Phone::IY},    // idea: iə
    {"i@3", Phone::IY},   // near: ɪɹ
    {";", Phone::Y},      // linking glide after i: before a vowel ("me all")
    {"O", Phone::AO},     // thought (short)
    {"O:", Phone::AO},    // thought
    {"O2", Phone::AO},    // unstressed thought
    {"O@", Phone::AO},    // north: ɔːɹ
    {"o@", Phone::AO},    // force: oːɹ
    {"O~", Phone::AO},    // nasal vowel in French loans
    {"OI", Phone::OY},    // choice
    {"oU", Phone::OW},    // goat
    {"U", Phone::UH},     // foot
    {"U@", Phone::UH},    // cure: ʊɹ
    {"u:", Phone::UW},    // goose
    {"b", Phone::B},
    {"d", Phone::D},
    {"D", Phone::DH},
    {"dZ", Phone::JH},
    {"f", Phone::F},
    {"g", Phone::G},
    {"h", Phone::HH},
    {"j", Phone::Y},
    {"k", Phone::K},
    {"x", Phone::K},      // velar fricative (loch): nearest visible shape is /k/
    {"C", Phone::HH},     // palatal fricative (German ich)
    {"l", Phone::L},
    {"l#", Phone::L},     // voiceless l (Welsh ll)
    {"m", Phone::M},
    {"m-", Phone::M},     // syllabic m
    {"n", Phone::N},
    {"n-", Phone::N},     // syllabic n (TIMIT en -> n)
    {"N", Phone::NG},
    {"p", Phone::P},
    {"r", Phone::R},
    {"r-", Phone::R},     // linking r after r-coloured vowels
    {"s", Phone::S},
    {"S", Phone::SH},
    {"t", Phone::T},
    {"t#", Phone::T},     // flap ɾ (TIMIT dx -> t)
    {"t2", Phone::T},     // unreleased t
    {"?", Phone::T},      // glottal stop: in en-us an allophone of /t/ ("certain")
    {"tS", Phone::CH},
    {"T", Phone::TH},
    {"v", Phone::V},
    {"w", Phone::W},
    {"z", Phone::Z},
    {"Z", Phone::ZH},
    {"_", Phone::SIL},    // pause
    {"_:", Phone::SIL},   // long pause (sentence end)
    {"_!", Phone::SIL},   // short pause (clause)
    {"_|", Phone::SIL},   // very short pause
});

// IPA (as `espeak-ng --ipa` and phoneme events in IPA mode write it) -> phones. Multi-character
// entries win over their prefixes (longest match). Length marks are part of the symbols.
inline constexpr auto kIpaMap = std::to_array<std::pair<std::string_view, Phone>>({
    {"ɑː", Phone::AA}, {"ɑ", Phone::AA}, {"ɒ", Phone::AA}, {"ɑ̃", Phone::AA},
    {"æ", Phone::AE}, {"a", Phone::AE},
    {"ʌ", Phone::AH}, {"ə", Phone::AX}, {"ɐ", Phone::AX},
    {"ɔː", Phone::AO}, {"ɔ", Phone::AO}, {"oː", Phone::AO}, {"ɔ̃", Phone::AO},
    {"aʊ", Phone::AW}, {"aɪ", Phone::AY},
    {"ɛ", Phone::EH}, {"e", Phone::EH},
    {"ɜː", Phone::ER}, {"ɝ", Phone::ER}, {"ɚ", Phone::ER}, {"ɜ", Phone::ER},
    {"eɪ", Phone::EY},
    {"ɪ", Phone::IH}, {"ᵻ", Phone::IH},
    {"iː", Phone::IY}, {"i", Phone::IY},
    {"oʊ", Phone::OW}, {"o", Phone::OW},
    {"ɔɪ", Phone::OY},
    {"ʊ", Phone::UH},
    {"uː", Phone::UW}, {"u", Phone::UW},
    {"b", Phone::B}, {"tʃ", Phone::CH}, {"d", Phone::D}, {"ð", Phone::DH}, {"f", Phone::F},
    {"ɡ", Phone::G}, {"g", Phone::G}, {"h", Phone::HH}, {"ç", Phone::HH}, {"dʒ", Phone::JH},
    {"k", Phone::K}, {"x", Phone::K}, {"l", Phone::L}, {"ɬ", Phone::L}, {"m", Phone::M},
    {"n", Phone::N}, {"ŋ", Phone::NG}, {"p", Phone::P}, {"ɹ", Phone::R}, {"r", Phone::R},
    {"s", Phone::S}, {"ʃ", Phone::SH}, {"t", Phone::T}, {"ɾ", Phone::T}, {"ʔ", Phone::T},
    {"θ", Phone::TH}, {"v", Phone::V}, {"w", Phone::W}, {"j", Phone::Y}, {"z", Phone::Z},
    {"ʒ", Phone::ZH},
    // Montreal Forced Aligner's IPA phone sets (english_mfa, english_us_mfa): diphthongs with a
    // glide, dark l, palatal stops before front vowels, and the rarer consonants.
    {"aj", Phone::AY}, {"aw", Phone::AW}, {"ej", Phone::EY}, {"ow", Phone::OW}, {"ɔj", Phone::OY},
    {"əw", Phone::OW}, {"ɫ", Phone::L}, {"ʎ", Phone::L}, {"c", Phone::K}, {"ɟ", Phone::G},
    {"ʈ", Phone::T}, {"ɖ", Phone::D}, {"ɱ", Phone::M}, {"ɲ", Phone::N}, {"ʋ", Phone::V},
    {"ʉ", Phone::UW}, {"ɛː", Phone::EH}, {"eː", Phone::EY}, {"ɒː", Phone::AA},
    // Praat's IPA chart symbols in hand-labelled grids (front rounded vowels have no English
    // phone: œ, ø, y go to the rounded central/back vowel a listener hears).
    {"œ", Phone::ER}, {"ø", Phone::ER}, {"y", Phone::UW},
});
// IPA marks that carry no phone: stress, syllable break, ties, secondary articulations,
// the syllabic diacritic (n̩ = n), word separators.
inline constexpr std::array<std::string_view, 16> kIpaIgnored{
    "ˈ", "ˌ", ".", " ", "_", "\u0361", "\u035C", "\u203F", "ʲ", "\u0329", "ː",
    "ʰ", "ʷ", "\u032A", "ˑ", "\u0303"};  // aspiration, labialisation, dental, half-long, nasal (MFA)

// A TIMIT/MOCHA label mapped to a phone. `closure` marks the closure half of a stop
// (bcl dcl gcl pcl tcl kcl): an importer merges it with the release that follows.
struct TimitPhone {
  Phone phone;
  bool closure;
  friend bool operator==(const TimitPhone&, const TimitPhone&) = default;
};

// TIMIT (and MOCHA-TIMIT, which uses the same labels) -> phones. The 61 TIMIT labels, folded as
// Lee & Hon (1989) fold them to 39, then to CMUdict's set, except that the schwas ax and ax-h stay
// apart from ah as AX (phone.hpp says why).
inline constexpr auto kTimitMap = std::to_array<std::pair<std::string_view, TimitPhone>>({
    {"iy", {Phone::IY, false}}, {"ih", {Phone::IH, false}}, {"eh", {Phone::EH, false}},
    {"ey", {Phone::EY, false}}, {"ae", {Phone::AE, false}}, {"aa", {Phone::AA, false}},
    {"aw", {Phone::AW, false}}, {"ay", {Phone::AY, false}}, {"ah", {Phone::AH, false}},
    {"ao", {Phone::AO, false}}, {"oy", {Phone::OY, false}}, {"ow", {Phone::OW, false}},
    {"uh", {Phone::UH, false}}, {"uw", {Phone::UW, false}},
    {"ux", {Phone::UW, false}},   // fronted u (dude) -> uw
    {"er", {Phone::ER, false}},
    {"axr", {Phone::ER, false}},  // unstressed er -> er
    {"ax", {Phone::AX, false}},   // schwa (CMUdict AH0)
    {"ix", {Phone::IH, false}},   // reduced i -> ih
    {"ax-h", {Phone::AX, false}}, // devoiced schwa -> ax
    {"b", {Phone::B, false}}, {"d", {Phone::D, false}}, {"g", {Phone::G, false}},
    {"p", {Phone::P, false}}, {"t", {Phone::T, false}}, {"k", {Phone::K, false}},
    {"bcl", {Phone::B, true}}, {"dcl", {Phone::D, true}}, {"gcl", {Phone::G, true}},
    {"pcl", {Phone::P, true}}, {"tcl", {Phone::T, true}}, {"kcl", {Phone::K, true}},
    {"dx", {Phone::T, false}},    // flap (butter): /t/ or /d/ in CMUdict; jaw and tongue as /t/
    {"q", {Phone::T, false}},     // glottal stop: mostly a /t/ allophone in AmE
    {"jh", {Phone::JH, false}}, {"ch", {Phone::CH, false}},
    {"s", {Phone::S, false}}, {"sh", {Phone::SH, false}}, {"z", {Phone::Z, false}},
    {"zh", {Phone::ZH, false}}, {"f", {Phone::F, false}}, {"th", {Phone::TH, false}},
    {"v", {Phone::V, false}}, {"dh", {Phone::DH, false}},
    {"m", {Phone::M, false}}, {"n", {Phone::N, false}}, {"ng", {Phone::NG, false}},
    {"em", {Phone::M, false}},    // syllabic m -> m
    {"en", {Phone::N, false}},    // syllabic n -> n
    {"eng", {Phone::NG, false}},  // syllabic ng -> ng
    {"nx", {Phone::N, false}},    // nasal flap (winner) -> n
    {"l", {Phone::L, false}}, {"r", {Phone::R, false}}, {"w", {Phone::W, false}},
    {"y", {Phone::Y, false}}, {"hh", {Phone::HH, false}},
    {"hv", {Phone::HH, false}},   // voiced h -> hh
    {"el", {Phone::L, false}},    // syllabic l -> l
    {"h#", {Phone::SIL, false}},  // utterance start/end
    {"pau", {Phone::SIL, false}}, // pause
    {"epi", {Phone::SIL, false}}, // epenthetic silence
    {"sil", {Phone::SIL, false}}, // MOCHA/HTK silence
    {"sp", {Phone::SIL, false}},  // HTK short pause
});

// The phone an espeak-ng en-us mnemonic stands for. Throws std::invalid_argument
// "<source>: unknown espeak-ng phoneme 'x'".
Phone phone_from_espeak(std::string_view mnemonic, std::string_view source);

// The phones an IPA string spells (longest match; stress, syllable and tie marks ignored).
// Throws std::invalid_argument "<source>: byte N: unknown IPA symbol 'x'".
std::vector<Phone> phones_from_ipa(std::string_view ipa, std::string_view source);

// The phone a TIMIT/MOCHA label stands for (case-insensitive; a trailing stress digit is
// not TIMIT and is refused). Throws std::invalid_argument "<source>: unknown TIMIT label 'x'".
TimitPhone phone_from_timit(std::string_view label, std::string_view source);

// An espeak-ng mnemonic that speaks the phone, for phoneme input ("[[...]]"); "_" for SIL.
std::string_view espeak_mnemonic(Phone p);

}  // namespace fapcast
