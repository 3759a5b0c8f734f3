#include "fapcast/phonetics/ipa_features.hpp"

#include "fapcast/core/utf8.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fapcast {

namespace {

using P = IpaPlace;
using M = IpaManner;
using H = IpaHeight;
using B = IpaBackness;

constexpr IpaSegment consonant(P place, M manner, bool voiced) {
  return {false, place, manner, voiced, H::kClose, B::kFront, false};
}
constexpr IpaSegment vowel(H height, B backness, bool rounded) {
  return {true, P::kGlottal, M::kApproximant, true, height, backness, rounded};
}

// The IPA chart (pulmonic consonants, other symbols, vowels), one row per letter, sorted by code
// point; espeak-ng's ASCII fallbacks (Kirshenbaum capitals) are the letters they stand for.
constexpr auto kLetters = std::to_array<std::pair<char32_t, IpaSegment>>({
    {U'?', consonant(P::kGlottal, M::kStop, false)},        // Kirshenbaum ʔ
    {U'@', vowel(H::kMid, B::kCentral, false)},              // ə
    {U'A', vowel(H::kOpen, B::kBack, false)},                // ɑ
    {U'C', consonant(P::kPalatal, M::kFricative, false)},    // ç
    {U'D', consonant(P::kDental, M::kFricative, true)},      // ð
    {U'E', vowel(H::kOpenMid, B::kFront, false)},            // ɛ
    {U'H', consonant(P::kGlottal, M::kFricative, true)},     // ɦ (espeak-ng hi: the H of बहुत)
    {U'I', vowel(H::kNearClose, B::kFront, false)},          // ɪ
    {U'J', consonant(P::kPalatal, M::kStop, true)},          // ɟ (espeak-ng hi: the J of आज)
    {U'L', consonant(P::kPalatal, M::kLateralApproximant, true)},  // ʎ
    {U'N', consonant(P::kVelar, M::kNasal, true)},           // ŋ
    {U'O', vowel(H::kOpenMid, B::kBack, true)},              // ɔ
    {U'Q', vowel(H::kOpen, B::kBack, true)},                 // ɒ
    {U'R', consonant(P::kAlveolar, M::kTrill, true)},        // espeak-ng's r-sounds (R R2 R3)
    {U'S', consonant(P::kPostalveolar, M::kFricative, false)},  // ʃ
    {U'T', consonant(P::kDental, M::kFricative, false)},     // θ
    {U'U', vowel(H::kNearClose, B::kBack, true)},            // ʊ
    {U'V', vowel(H::kOpenMid, B::kBack, false)},             // ʌ
    {U'X', consonant(P::kUvular, M::kFricative, false)},     // χ
    {U'Z', consonant(P::kPostalveolar, M::kFricative, true)},   // ʒ
    {U'a', vowel(H::kOpen, B::kFront, false)},
    {U'b', consonant(P::kBilabial, M::kStop, true)},
    {U'c', consonant(P::kPalatal, M::kStop, false)},
    {U'd', consonant(P::kAlveolar, M::kStop, true)},
    {U'e', vowel(H::kCloseMid, B::kFront, false)},
    {U'f', consonant(P::kLabiodental, M::kFricative, false)},
    {U'g', consonant(P::kVelar, M::kStop, true)},
    {U'h', consonant(P::kGlottal, M::kFricative, false)},
    {U'i', vowel(H::kClose, B::kFront, false)},
    {U'j', consonant(P::kPalatal, M::kApproximant, true)},
    {U'k', consonant(P::kVelar, M::kStop, false)},
    {U'l', consonant(P::kAlveolar, M::kLateralApproximant, true)},
    {U'm', consonant(P::kBilabial, M::kNasal, true)},
    {U'n', consonant(P::kAlveolar, M::kNasal, true)},
    {U'o', vowel(H::kCloseMid, B::kBack, true)},
    {U'p', consonant(P::kBilabial, M::kStop, false)},
    {U'q', consonant(P::kUvular, M::kStop, false)},
    {U'r', consonant(P::kAlveolar, M::kTrill, true)},
    {U's', consonant(P::kAlveolar, M::kFricative, false)},
    {U't', consonant(P::kAlveolar, M::kStop, false)},
    {U'u', vowel(H::kClose, B::kBack, true)},
    {U'v', consonant(P::kLabiodental, M::kFricative, true)},
    {U'w', consonant(P::kLabialVelar, M::kApproximant, true)},
    {U'x', consonant(P::kVelar, M::kFricative, false)},
    {U'y', vowel(H::kClose, B::kFront, true)},
    {U'z', consonant(P::kAlveolar, M::kFricative, true)},
    {U'\u00E4', vowel(H::kOpen, B::kCentral, false)},        // ä
    {U'\u00E6', vowel(H::kNearOpen, B::kFront, false)},      // æ
    {U'\u00E7', consonant(P::kPalatal, M::kFricative, false)},  // ç
    {U'\u00F0', consonant(P::kDental, M::kFricative, true)},    // ð
    {U'\u00F8', vowel(H::kCloseMid, B::kFront, true)},       // ø
    {U'\u0127', consonant(P::kPharyngeal, M::kFricative, false)},  // ħ
    {U'\u014B', consonant(P::kVelar, M::kNasal, true)},      // ŋ
    {U'\u0153', vowel(H::kOpenMid, B::kFront, true)},        // œ
    {U'\u0250', vowel(H::kNearOpen, B::kCentral, false)},    // ɐ
    {U'\u0251', vowel(H::kOpen, B::kBack, false)},           // ɑ
    {U'\u0252', vowel(H::kOpen, B::kBack, true)},            // ɒ
    {U'\u0254', vowel(H::kOpenMid, B::kBack, true)},         // ɔ
    {U'\u0255', consonant(P::kAlveoloPalatal, M::kFricative, false)},  // ɕ
    {U'\u0256', consonant(P::kRetroflex, M::kStop, true)},   // ɖ
    {U'\u0258', vowel(H::kCloseMid, B::kCentral, false)},    // ɘ
    {U'\u0259', vowel(H::kMid, B::kCentral, false)},         // ə
    {U'\u025A', vowel(H::kOpenMid, B::kCentral, false)},     // ɚ (r-coloured: as ɜ)
    {U'\u025B', vowel(H::kOpenMid, B::kFront, false)},       // ɛ
    {U'\u025C', vowel(H::kOpenMid, B::kCentral, false)},     // ɜ
    {U'\u025D', vowel(H::kOpenMid, B::kCentral, false)},     // ɝ (r-coloured: as ɜ)
    {U'\u025E', vowel(H::kOpenMid, B::kCentral, true)},      // ɞ
    {U'\u025F', consonant(P::kPalatal, M::kStop, true)},     // ɟ
    {U'\u0260', consonant(P::kVelar, M::kStop, true)},       // ɠ (implosive)
    {U'\u0261', consonant(P::kVelar, M::kStop, true)},       // ɡ
    {U'\u0262', consonant(P::kUvular, M::kStop, true)},      // ɢ
    {U'\u0263', consonant(P::kVelar, M::kFricative, true)},  // ɣ
    {U'\u0264', vowel(H::kCloseMid, B::kBack, false)},       // ɤ
    {U'\u0265', consonant(P::kLabialPalatal, M::kApproximant, true)},  // ɥ
    {U'\u0266', consonant(P::kGlottal, M::kFricative, true)},  // ɦ
    {U'\u0267', consonant(P::kPostalveolar, M::kFricative, false)},  // ɧ
    {U'\u0268', vowel(H::kClose, B::kCentral, false)},       // ɨ
    {U'\u026A', vowel(H::kNearClose, B::kFront, false)},     // ɪ
    {U'\u026B', consonant(P::kAlveolar, M::kLateralApproximant, true)},  // ɫ
    {U'\u026C', consonant(P::kAlveolar, M::kLateralFricative, false)},   // ɬ
    {U'\u026D', consonant(P::kRetroflex, M::kLateralApproximant, true)}, // ɭ
    {U'\u026E', consonant(P::kAlveolar, M::kLateralFricative, true)},    // ɮ
    {U'\u026F', vowel(H::kClose, B::kBack, false)},          // ɯ
    {U'\u0270', consonant(P::kVelar, M::kApproximant, true)},  // ɰ
    {U'\u0271', consonant(P::kLabiodental, M::kNasal, true)},  // ɱ
    {U'\u0272', consonant(P::kPalatal, M::kNasal, true)},    // ɲ
    {U'\u0273', consonant(P::kRetroflex, M::kNasal, true)},  // ɳ
    {U'\u0274', consonant(P::kUvular, M::kNasal, true)},     // ɴ
    {U'\u0275', vowel(H::kCloseMid, B::kCentral, true)},     // ɵ
    {U'\u0276', vowel(H::kOpen, B::kFront, true)},           // ɶ
    {U'\u0278', consonant(P::kBilabial, M::kFricative, false)},  // ɸ
    {U'\u0279', consonant(P::kAlveolar, M::kApproximant, true)},  // ɹ
    {U'\u027A', consonant(P::kAlveolar, M::kLateralApproximant, true)},  // ɺ (lateral flap)
    {U'\u027B', consonant(P::kRetroflex, M::kApproximant, true)},  // ɻ
    {U'\u027D', consonant(P::kRetroflex, M::kTap, true)},    // ɽ
    {U'\u027E', consonant(P::kAlveolar, M::kTap, true)},     // ɾ
    {U'\u0280', consonant(P::kUvular, M::kTrill, true)},     // ʀ
    {U'\u0281', consonant(P::kUvular, M::kFricative, true)}, // ʁ
    {U'\u0282', consonant(P::kRetroflex, M::kFricative, false)},  // ʂ
    {U'\u0283', consonant(P::kPostalveolar, M::kFricative, false)},  // ʃ
    {U'\u0288', consonant(P::kRetroflex, M::kStop, false)},  // ʈ
    {U'\u0289', vowel(H::kClose, B::kCentral, true)},        // ʉ
    {U'\u028A', vowel(H::kNearClose, B::kBack, true)},       // ʊ
    {U'\u028B', consonant(P::kLabiodental, M::kApproximant, true)},  // ʋ
    {U'\u028C', vowel(H::kOpenMid, B::kBack, false)},        // ʌ
    {U'\u028D', consonant(P::kLabialVelar, M::kFricative, false)},  // ʍ
    {U'\u028E', consonant(P::kPalatal, M::kLateralApproximant, true)},  // ʎ
    {U'\u028F', vowel(H::kNearClose, B::kFront, true)},      // ʏ
    {U'\u0290', consonant(P::kRetroflex, M::kFricative, true)},  // ʐ
    {U'\u0291', consonant(P::kAlveoloPalatal, M::kFricative, true)},  // ʑ
    {U'\u0292', consonant(P::kPostalveolar, M::kFricative, true)},  // ʒ
    {U'\u0294', consonant(P::kGlottal, M::kStop, false)},    // ʔ
    {U'\u0295', consonant(P::kPharyngeal, M::kFricative, true)},  // ʕ
    {U'\u0299', consonant(P::kBilabial, M::kTrill, true)},   // ʙ
    {U'\u029D', consonant(P::kPalatal, M::kFricative, true)},  // ʝ
    {U'\u029F', consonant(P::kVelar, M::kLateralApproximant, true)},  // ʟ
    {U'\u02A1', consonant(P::kPharyngeal, M::kStop, false)},  // ʡ
    {U'\u03B2', consonant(P::kBilabial, M::kFricative, true)},  // β
    {U'\u03B5', vowel(H::kOpenMid, B::kFront, false)},       // Greek ε for ɛ
    {U'\u03B8', consonant(P::kDental, M::kFricative, false)},  // θ
    {U'\u03C7', consonant(P::kUvular, M::kFricative, false)},  // χ
    {U'\u1D7B', vowel(H::kNearClose, B::kCentral, false)},   // ᵻ
    {U'\u2C71', consonant(P::kLabiodental, M::kTap, true)},  // ⱱ
});

static_assert(std::is_sorted(kLetters.begin(), kLetters.end(),
                             [](const auto& a, const auto& b) { return a.first < b.first; }),
              "kLetters must be sorted by code point (ipa_segment searches it)");

// Ligatures: two letters in one code point.
constexpr auto kLigatures = std::to_array<std::pair<char32_t, std::pair<char32_t, char32_t>>>({
    {U'\u02A3', {U'd', U'z'}}, {U'\u02A4', {U'd', U'\u0292'}}, {U'\u02A5', {U'd', U'\u0291'}},
    {U'\u02A6', {U't', U's'}}, {U'\u02A7', {U't', U'\u0283'}}, {U'\u02A8', {U't', U'\u0255'}},
});

// Diacritics, suprasegmentals, tone marks and espeak-ng's ASCII modifiers: skipped.
bool is_modifier(char32_t c) {
  if (c < 0x80) {
    if (c >= '0' && c <= '9') return true;  // tone numbers, variant digits
    static constexpr std::string_view kAscii = "#-^[]`'.,:;!~+=|\"/*&<>$%{}\\";
    return kAscii.find(static_cast<char>(c)) != std::string_view::npos;
  }
  return (c >= 0x02B0 && c <= 0x02FF) ||  // spacing modifier letters (ʰ ʲ ʷ ː ˈ ˌ ˞ tone letters)
         (c >= 0x0300 && c <= 0x036F) ||                 // combining diacritics, ties
         (c >= 0x1AB0 && c <= 0x1AFF) || (c >= 0x1DC0 && c <= 0x1DFF) ||
         (c >= 0x1D2C && c <= 0x1D6A) || c == 0x207F ||  // superscript letters (ᵐ ⁿ)
         c == 0x2191 || c == 0x2193 || c == 0x2197 || c == 0x2198;  // up/downstep, global rise/fall
}

std::string code_point_name(char32_t c) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "U+%04X", static_cast<unsigned>(c));
  return buffer;
}

// Bytes of `text` with control bytes as \xNN (for error messages).
std::string shown(std::string_view text) {
  std::string out;
  for (const char ch : text) {
    const auto b = static_cast<unsigned char>(ch);
    if (b < 0x20 || b == 0x7F) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02X", b);
      out += buffer;
    } else {
      out += ch;
    }
  }
  return out;
}

struct CodePoint {
  char32_t value;
  std::string_view bytes;  // its UTF-8 in the text
};

// The code points of `text`; throws on invalid UTF-8.
std::vector<CodePoint> decode(std::string_view text, std::string_view source) {
  std::vector<CodePoint> out;
  std::size_t i = 0;
  while (i < text.size()) {
    const Utf8CodePoint decoded = decode_utf8_at(text, i);
    if (decoded.error) {
      throw std::invalid_argument(std::string(source) + ": invalid UTF-8 at byte " + std::to_string(i) +
                                  " in phoneme '" + shown(text) + "'");
    }
    const char32_t c = decoded.value;
    const std::size_t n = decoded.bytes;
    out.push_back({c, text.substr(i, n)});
    i += n;
  }
  return out;
}

// Fricatives behind the alveolar ridge: with a stop before them, the affricates CH JH.
bool postalveolar_like(IpaPlace p) {
  return p == P::kPostalveolar || p == P::kRetroflex || p == P::kAlveoloPalatal;
}

Phone vowel_phone(const IpaSegment& v) {
  const auto h = static_cast<int>(v.height);
  if (!v.rounded) {
    switch (v.backness) {
      case B::kFront: return h == 0 ? Phone::IY : h == 1 ? Phone::IH : h <= 4 ? Phone::EH : Phone::AE;
      case B::kCentral: return h <= 1 ? Phone::IH : h == 4 ? Phone::ER : h == 6 ? Phone::AA : Phone::AX;  // ɘ ə ɐ
      case B::kBack: return h <= 1 ? Phone::IH : h <= 4 ? Phone::AH : Phone::AA;
    }
  }
  switch (v.backness) {
    case B::kFront:
    case B::kCentral: return h == 0 ? Phone::UW : h == 1 ? Phone::UH : h <= 4 ? Phone::ER : Phone::AO;
    case B::kBack: return h == 0 ? Phone::UW : h == 1 ? Phone::UH : h <= 3 ? Phone::OW : h <= 5 ? Phone::AO : Phone::AA;
  }
  return Phone::AH;
}

Phone consonant_phone(const IpaSegment& c) {
  const bool v = c.voiced;
  switch (c.manner) {
    case M::kStop:
      switch (c.place) {
        case P::kBilabial: case P::kLabiodental: return v ? Phone::B : Phone::P;
        case P::kPalatal: case P::kLabialPalatal: case P::kVelar: case P::kLabialVelar: case P::kUvular:
          return v ? Phone::G : Phone::K;
        default: return v ? Phone::D : Phone::T;  // coronal; glottal/pharyngeal as en-us ʔ -> T
      }
    case M::kNasal:
      if (c.place == P::kBilabial || c.place == P::kLabiodental) return Phone::M;
      if (c.place == P::kVelar || c.place == P::kUvular) return Phone::NG;
      return Phone::N;
    case M::kTrill:
      if (c.place == P::kBilabial) return Phone::B;
      if (c.place == P::kUvular) return Phone::G;
      return Phone::R;
    case M::kTap: return c.place == P::kLabiodental ? Phone::V : Phone::T;
    case M::kFricative:
      switch (c.place) {
        case P::kBilabial: case P::kLabiodental: return v ? Phone::V : Phone::F;
        case P::kDental: return v ? Phone::DH : Phone::TH;
        case P::kAlveolar: return v ? Phone::Z : Phone::S;
        case P::kPostalveolar: case P::kRetroflex: case P::kAlveoloPalatal: return v ? Phone::ZH : Phone::SH;
        case P::kPalatal: return v ? Phone::Y : Phone::HH;
        case P::kLabialPalatal: case P::kLabialVelar: return Phone::W;
        case P::kVelar: case P::kUvular: return v ? Phone::G : Phone::K;
        case P::kPharyngeal: case P::kGlottal: return Phone::HH;
      }
      return Phone::HH;
    case M::kLateralFricative:
    case M::kLateralApproximant: return Phone::L;
    case M::kApproximant:
      switch (c.place) {
        case P::kBilabial: case P::kLabiodental: return Phone::V;
        case P::kDental: case P::kAlveolar: case P::kPostalveolar: case P::kRetroflex: return Phone::R;
        case P::kAlveoloPalatal: case P::kPalatal: return Phone::Y;
        case P::kLabialPalatal: case P::kLabialVelar: return Phone::W;
        case P::kVelar: case P::kUvular: return Phone::G;
        case P::kPharyngeal: case P::kGlottal: return Phone::HH;
      }
      return Phone::HH;
  }
  return Phone::HH;
}

// The diphthong a nucleus and a close offglide make, or the nucleus alone.
Phone diphthong(const IpaSegment& nucleus, const IpaSegment& glide) {
  const Phone n = vowel_phone(nucleus);
  const bool close_glide = glide.height <= H::kNearClose;
  if (!close_glide || nucleus.height <= H::kNearClose) return n;
  const bool open = nucleus.height >= H::kNearOpen;
  if (glide.backness == B::kFront && !glide.rounded) {
    if (open) return Phone::AY;
    if (nucleus.rounded && nucleus.backness == B::kBack) return Phone::OY;
    return nucleus.backness == B::kFront ? Phone::EY : n;
  }
  if (glide.rounded && glide.backness != B::kFront) return open ? Phone::AW : Phone::OW;
  return n;
}

}  // namespace

std::optional<IpaSegment> ipa_segment(char32_t code_point) {
  const auto* it = std::lower_bound(kLetters.begin(), kLetters.end(), code_point,
                                    [](const auto& row, char32_t c) { return row.first < c; });
  if (it == kLetters.end() || it->first != code_point) return std::nullopt;
  return it->second;
}

Phone phone_from_features(const IpaSegment& segment) {
  return segment.vowel ? vowel_phone(segment) : consonant_phone(segment);
}

std::optional<Phone> phone_from_ipa_features(std::string_view ipa, std::string_view source) {
  if (ipa.empty() || ipa.front() == '_') return Phone::SIL;
  if (ipa.front() == '(') return std::nullopt;  // language switch "(en)", maybe cut: "(en-us-n"
  std::vector<IpaSegment> segments;
  for (const CodePoint& point : decode(ipa, source)) {
    const char32_t c = point.value;
    if (const auto s = ipa_segment(c)) {
      segments.push_back(*s);
      continue;
    }
    const auto* lig = std::find_if(kLigatures.begin(), kLigatures.end(), [&](const auto& row) { return row.first == c; });
    if (lig != kLigatures.end()) {
      segments.push_back(*ipa_segment(lig->second.first));
      segments.push_back(*ipa_segment(lig->second.second));
      continue;
    }
    if (is_modifier(c)) continue;
    throw std::invalid_argument(std::string(source) + ": unknown IPA symbol '" + shown(point.bytes) +
                                "' (" + code_point_name(c) +
                                ") in phoneme '" + shown(ipa) + "'");
  }
  if (segments.empty()) return std::nullopt;
  // Vowels decide: the most open is the nucleus, the last close vowel after it its glide.
  const IpaSegment* nucleus = nullptr;
  for (const IpaSegment& s : segments) {
    if (s.vowel && (nucleus == nullptr || s.height > nucleus->height)) nucleus = &s;
  }
  if (nucleus != nullptr) {
    const IpaSegment* glide = nullptr;
    for (const IpaSegment* s = nucleus + 1; s != segments.data() + segments.size(); ++s) {
      if (s->vowel) glide = s;
    }
    return glide == nullptr ? vowel_phone(*nucleus) : diphthong(*nucleus, *glide);
  }
  const IpaSegment& first = segments.front();
  if (first.manner == M::kStop && segments.size() > 1 && segments[1].manner == M::kFricative &&
      postalveolar_like(segments[1].place)) {
    return first.voiced ? Phone::JH : Phone::CH;
  }
  return consonant_phone(first);
}

}  // namespace fapcast
