#pragma once
// Phone classes from IPA features: how the text front-end maps the phonemes of every espeak-ng
// language (their IPA as espeak-ng's phoneme events report it) into the internal phone set.
// No per-language list: each IPA letter carries its chart features (consonants: place, manner,
// voicing; vowels: height, backness, rounding) and the phone follows from the features
// (spec/phones.md, "Phones from IPA features").
#include <cstdint>
#include <optional>
#include <string_view>

#include "fapcast/phonetics/phone.hpp"

namespace fapcast {

enum class IpaPlace : std::uint8_t {
  kBilabial, kLabiodental, kDental, kAlveolar, kPostalveolar, kRetroflex, kAlveoloPalatal,
  kPalatal, kLabialPalatal, kLabialVelar, kVelar, kUvular, kPharyngeal, kGlottal
};
enum class IpaManner : std::uint8_t {
  kStop, kNasal, kTrill, kTap, kFricative, kLateralFricative, kApproximant, kLateralApproximant
};
// Vowel height on the IPA chart's seven rows, close (0) to open (6).
enum class IpaHeight : std::uint8_t { kClose, kNearClose, kCloseMid, kMid, kOpenMid, kNearOpen, kOpen };
enum class IpaBackness : std::uint8_t { kFront, kCentral, kBack };

// One IPA letter's features. For a consonant `height`/`backness` are unused; for a vowel
// `place`/`manner` are.
struct IpaSegment {
  bool vowel;
  IpaPlace place;
  IpaManner manner;
  bool voiced;
  IpaHeight height;
  IpaBackness backness;
  bool rounded;
};

// The features of one code point that is an IPA letter (or one of espeak-ng's ASCII fallbacks
// for a phoneme without IPA: Kirshenbaum capitals such as `A N S`, `R` for its r-sounds, `H J L`, `?`
// for ʔ); nullopt for
// anything else.
std::optional<IpaSegment> ipa_segment(char32_t code_point);

// The phone of one segment by its features.
Phone phone_from_features(const IpaSegment& segment);

// The phone class of one espeak-ng phoneme given as IPA (one event's name, e.g. "oː", "tʃʰ",
// "aɪ", "d̻͡z̪"): diacritics, length, stress, ties and tone digits are skipped; among several
// vowels the most open is the nucleus and a close vowel after it makes a diphthong (aɪ -> AY,
// oʊ -> OW); a stop followed by a postalveolar-like fricative is an affricate (CH JH), by any
// other fricative the stop; otherwise the first consonant. Empty, "_" (pause) -> SIL.
// nullopt: nothing to say — an event that only switches language ("(en)", also when cut short
// as "(en-us-n") or carries a
// modifier alone ("ʲ"); the caller extends the phone before it.
// Throws std::invalid_argument "<source>: unknown IPA symbol 'X' (U+XXXX) in phoneme 'P'" for a
// code point that is neither a letter nor a known modifier, and for invalid UTF-8.
std::optional<Phone> phone_from_ipa_features(std::string_view ipa, std::string_view source);

}  // namespace fapcast
