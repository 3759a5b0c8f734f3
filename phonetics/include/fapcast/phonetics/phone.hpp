#pragma once
// The internal phone set: the 39 ARPAbet phones of CMUdict (the set TIMIT-trained aligners fold
// to), AX for the reduced vowel schwa, and SIL for silence and pauses. CMUdict writes schwa AH0
// and TIMIT's 39-phone folding merges ax into ah; they are kept apart here because the schwa is
// seen as a small, neutral opening and AH as a wide one (spec/phones.md "Schwa"). Stress is not
// part of a phone; it travels beside it.
// Maps from other symbol sets live in phone_map.hpp; visemes in viseme.hpp; spec/phones.md.
#include <array>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string_view>

namespace fapcast {

enum class Phone : std::uint8_t {
  AA, AE, AH, AO, AW, AX, AY, EH, ER, EY, IH, IY, OW, OY, UH, UW,  // 16 vowels
  B, CH, D, DH, F, G, HH, JH, K, L, M, N, NG, P, R, S, SH, T, TH, V, W, Y, Z, ZH,  // 24 consonants
  SIL,  // silence or pause (utterance edges, espeak-ng "_", TIMIT h#/pau/epi)
};

inline constexpr std::size_t kPhoneCount = 41;

// Manner of articulation (vowels and diphthongs count as manners here).
enum class Manner : std::uint8_t {
  kVowel, kDiphthong, kStop, kAffricate, kFricative, kNasal, kLiquid, kGlide, kSilence
};

// Place of the constriction that is visible (or not) on the face; vowels use tongue position.
enum class Place : std::uint8_t {
  kBilabial, kLabiodental, kDental, kAlveolar, kPostalveolar, kPalatal, kVelar, kLabialVelar,
  kGlottal, kFront, kCentral, kBack, kNone
};

struct PhoneInfo {
  Phone phone;
  std::string_view arpabet;  // CMUdict spelling, upper case, no stress digit
  std::string_view ipa;      // broad General American IPA
  Manner manner;
  Place place;
  bool voiced;
  bool rounded;              // lips rounded/protruded at the phone's target
};

// One row per phone, in enum order (a test checks the order).
inline constexpr std::array<PhoneInfo, kPhoneCount> kPhoneTable{{
    // phone        arpabet ipa   manner              place                 voiced rounded
    {Phone::AA,  "AA", "ɑ",  Manner::kVowel,     Place::kBack,         true,  false},  // father, lot
    {Phone::AE,  "AE", "æ",  Manner::kVowel,     Place::kFront,        true,  false},  // cat
    {Phone::AH,  "AH", "ʌ",  Manner::kVowel,     Place::kCentral,      true,  false},  // cut
    {Phone::AO,  "AO", "ɔ",  Manner::kVowel,     Place::kBack,         true,  true},   // thought
    {Phone::AW,  "AW", "aʊ", Manner::kDiphthong, Place::kBack,         true,  true},   // mouth (ends rounded)
    {Phone::AX,  "AX", "ə",  Manner::kVowel,     Place::kCentral,      true,  false},  // comma; CMUdict AH0
    {Phone::AY,  "AY", "aɪ", Manner::kDiphthong, Place::kFront,        true,  false},  // price
    {Phone::EH,  "EH", "ɛ",  Manner::kVowel,     Place::kFront,        true,  false},  // dress
    {Phone::ER,  "ER", "ɝ",  Manner::kVowel,     Place::kCentral,      true,  true},   // nurse; ER0 = ɚ
    {Phone::EY,  "EY", "eɪ", Manner::kDiphthong, Place::kFront,        true,  false},  // face
    {Phone::IH,  "IH", "ɪ",  Manner::kVowel,     Place::kFront,        true,  false},  // kit
    {Phone::IY,  "IY", "i",  Manner::kVowel,     Place::kFront,        true,  false},  // fleece
    {Phone::OW,  "OW", "oʊ", Manner::kDiphthong, Place::kBack,         true,  true},   // goat
    {Phone::OY,  "OY", "ɔɪ", Manner::kDiphthong, Place::kBack,         true,  true},   // choice (starts rounded)
    {Phone::UH,  "UH", "ʊ",  Manner::kVowel,     Place::kBack,         true,  true},   // foot
    {Phone::UW,  "UW", "u",  Manner::kVowel,     Place::kBack,         true,  true},   // goose
    {Phone::B,   "B",  "b",  Manner::kStop,      Place::kBilabial,     true,  false},
    {Phone::CH,  "CH", "tʃ", Manner::kAffricate, Place::kPostalveolar, false, true},   // lips protrude
    {Phone::D,   "D",  "d",  Manner::kStop,      Place::kAlveolar,     true,  false},
    {Phone::DH,  "DH", "ð",  Manner::kFricative, Place::kDental,       true,  false},
    {Phone::F,   "F",  "f",  Manner::kFricative, Place::kLabiodental,  false, false},
    {Phone::G,   "G",  "ɡ",  Manner::kStop,      Place::kVelar,        true,  false},
    {Phone::HH,  "HH", "h",  Manner::kFricative, Place::kGlottal,      false, false},
    {Phone::JH,  "JH", "dʒ", Manner::kAffricate, Place::kPostalveolar, true,  true},
    {Phone::K,   "K",  "k",  Manner::kStop,      Place::kVelar,        false, false},
    {Phone::L,   "L",  "l",  Manner::kLiquid,    Place::kAlveolar,     true,  false},
    {Phone::M,   "M",  "m",  Manner::kNasal,     Place::kBilabial,     true,  false},
    {Phone::N,   "N",  "n",  Manner::kNasal,     Place::kAlveolar,     true,  false},
    {Phone::NG,  "NG", "ŋ",  Manner::kNasal,     Place::kVelar,        true,  false},
    {Phone::P,   "P",  "p",  Manner::kStop,      Place::kBilabial,     false, false},
    {Phone::R,   "R",  "ɹ",  Manner::kLiquid,    Place::kPostalveolar, true,  true},   // AmE r is rounded
    {Phone::S,   "S",  "s",  Manner::kFricative, Place::kAlveolar,     false, false},
    {Phone::SH,  "SH", "ʃ",  Manner::kFricative, Place::kPostalveolar, false, true},
    {Phone::T,   "T",  "t",  Manner::kStop,      Place::kAlveolar,     false, false},
    {Phone::TH,  "TH", "θ",  Manner::kFricative, Place::kDental,       false, false},
    {Phone::V,   "V",  "v",  Manner::kFricative, Place::kLabiodental,  true,  false},
    {Phone::W,   "W",  "w",  Manner::kGlide,     Place::kLabialVelar,  true,  true},
    {Phone::Y,   "Y",  "j",  Manner::kGlide,     Place::kPalatal,      true,  false},
    {Phone::Z,   "Z",  "z",  Manner::kFricative, Place::kAlveolar,     true,  false},
    {Phone::ZH,  "ZH", "ʒ",  Manner::kFricative, Place::kPostalveolar, true,  true},
    {Phone::SIL, "SIL", "",  Manner::kSilence,   Place::kNone,         false, false},
}};

// The table row of a phone.
constexpr const PhoneInfo& phone_info(Phone p) { return kPhoneTable[static_cast<std::size_t>(p)]; }

// The ARPAbet name of a phone ("AA" ... "ZH", "SIL").
constexpr std::string_view arpabet(Phone p) { return phone_info(p).arpabet; }

// Prints the ARPAbet symbol (tests show what they saw).
std::ostream& operator<<(std::ostream& out, Phone p);

// True for vowels and diphthongs (the syllable nuclei).
constexpr bool is_vowel(Phone p) {
  return phone_info(p).manner == Manner::kVowel || phone_info(p).manner == Manner::kDiphthong;
}

// True for phones whose lips or tongue close the tract before a release: stops and affricates,
// and /m/ (the lips close for it as for /p b/). Their visual segment begins at the closure.
constexpr bool has_closure(Phone p) {
  const Manner m = phone_info(p).manner;
  return m == Manner::kStop || m == Manner::kAffricate || p == Phone::M;
}

// Lexical stress as CMUdict writes it: 0 none, 1 primary, 2 secondary.
enum class Stress : std::uint8_t { kNone = 0, kPrimary = 1, kSecondary = 2 };

// A phone with its stress, if the source gave one (vowels in CMUdict always have it).
struct StressedPhone {
  Phone phone;
  std::optional<Stress> stress;
  friend bool operator==(const StressedPhone&, const StressedPhone&) = default;
};

// Parses an ARPAbet symbol, any case, with an optional stress digit 0-2 ("AH0", "ax", "sil").
// Throws std::invalid_argument "<source>: unknown ARPAbet phone 'x'" naming the symbol.
StressedPhone parse_arpabet(std::string_view symbol, std::string_view source);

}  // namespace fapcast
