#pragma once
// Two viseme sets over the phone set (phone.hpp):
//  - VisemeClass: the 21 classes the unit search matches on (paper section 3.7: a unit fits a
//    target phone iff their classes agree) and for which the 21 visual prototypes are built
//    (section 3.4). Phones share a class when lips, jaw and visible tongue take the same shape.
//  - Mpeg4Viseme: the 15 values (0 = none, 1..14) of FAP 1 viseme_select.
// Both are constexpr tables with one row per phone; spec/visemes.tsv is checked against them.
#include <array>
#include <cstdint>
#include <string_view>

#include "fapcast/phonetics/phone.hpp"

namespace fapcast {

enum class VisemeClass : std::uint8_t {
  kSilence,           // SIL: lips at rest
  kBilabial,          // P B M: lips pressed together
  kLabiodental,       // F V: lower lip against upper teeth
  kDental,            // TH DH: tongue tip visible between the teeth
  kAlveolar,          // T D N: jaw nearly closed, tongue tip behind upper teeth, lips neutral
  kSibilant,          // S Z: teeth almost touching, lips spread, narrow slit
  kLateral,           // L: tongue tip up and visible, jaw a little more open than T D N
  kPostalveolar,      // SH ZH CH JH: lips protruded and flared (funnel)
  kRhotic,            // R ER: lips slightly rounded and protruded, tongue bunched
  kBack,              // K G NG HH: constriction invisible; jaw half open, lips from context
  kLabialVelar,       // W: tight rounding and protrusion
  kCloseFront,        // IY Y: lips spread, jaw nearly closed
  kNearCloseFront,    // IH: spread, a little more open than IY
  kMidFront,          // EH EY: spread, jaw half open
  kOpenFront,         // AE: wide spread, jaw open
  kOpenUnrounded,     // AA AH AY: jaw wide open, lips neutral (AY starts here)
  kOpenMidRounded,    // AO OY AW: jaw open, lips rounded (OY starts here, AW ends here)
  kMidRounded,        // OW: rounded, moving toward a close rounding
  kNearCloseRounded,  // UH: loosely rounded, jaw nearly closed
  kCloseRounded,      // UW: tight rounding, strongest protrusion of the vowels
  kSchwa,             // AX: the reduced vowel, a small neutral opening (lips neither round nor spread)
};

inline constexpr std::size_t kVisemeClassCount = 21;

// The MPEG-4 visemes of FAP 1 (viseme_select1/2), with the standard's example phones.
enum class Mpeg4Viseme : std::uint8_t {
  kNone = 0,  // no viseme (silence)
  kPBM = 1,   // p b m
  kFV = 2,    // f v
  kTHDH = 3,  // T D (think, that)
  kTD = 4,    // t d
  kKG = 5,    // k g
  kCHJSH = 6, // tS dZ S (chair, join, she)
  kSZ = 7,    // s z
  kNL = 8,    // n l
  kR = 9,     // r
  kA = 10,    // A: (car)
  kE = 11,    // e (bed)
  kI = 12,    // I (tip)
  kO = 13,    // O (top)
  kU = 14,    // U (book)
};

inline constexpr std::size_t kMpeg4VisemeCount = 15;

struct VisemeRow {
  Phone phone;
  VisemeClass search_class;
  Mpeg4Viseme mpeg4;
};

// One row per phone in phone order. MPEG-4 has no class for several phones; the nearest
// shape is chosen (reason in the comment) and spec/phones.md lists these choices.
inline constexpr std::array<VisemeRow, kPhoneCount> kVisemeTable{{
    {Phone::AA, VisemeClass::kOpenUnrounded, Mpeg4Viseme::kA},
    {Phone::AE, VisemeClass::kOpenFront, Mpeg4Viseme::kE},        // open spread: nearer e than A:
    {Phone::AH, VisemeClass::kOpenUnrounded, Mpeg4Viseme::kA},    // open central, unrounded
    {Phone::AO, VisemeClass::kOpenMidRounded, Mpeg4Viseme::kO},
    {Phone::AW, VisemeClass::kOpenMidRounded, Mpeg4Viseme::kA},   // open jaw, ends rounded; FAP 1: nucleus a
    {Phone::AX, VisemeClass::kSchwa, Mpeg4Viseme::kE},            // mid central: nearest the mid e
    {Phone::AY, VisemeClass::kOpenUnrounded, Mpeg4Viseme::kA},    // nucleus a
    {Phone::EH, VisemeClass::kMidFront, Mpeg4Viseme::kE},
    {Phone::ER, VisemeClass::kRhotic, Mpeg4Viseme::kR},           // r-coloured: lips as for r
    {Phone::EY, VisemeClass::kMidFront, Mpeg4Viseme::kE},         // nucleus e
    {Phone::IH, VisemeClass::kNearCloseFront, Mpeg4Viseme::kI},
    {Phone::IY, VisemeClass::kCloseFront, Mpeg4Viseme::kI},       // closest spread vowel is I
    {Phone::OW, VisemeClass::kMidRounded, Mpeg4Viseme::kO},       // nucleus o: rounded, mid
    {Phone::OY, VisemeClass::kOpenMidRounded, Mpeg4Viseme::kO},   // nucleus O
    {Phone::UH, VisemeClass::kNearCloseRounded, Mpeg4Viseme::kU},
    {Phone::UW, VisemeClass::kCloseRounded, Mpeg4Viseme::kU},     // close rounded: U
    {Phone::B, VisemeClass::kBilabial, Mpeg4Viseme::kPBM},
    {Phone::CH, VisemeClass::kPostalveolar, Mpeg4Viseme::kCHJSH},
    {Phone::D, VisemeClass::kAlveolar, Mpeg4Viseme::kTD},
    {Phone::DH, VisemeClass::kDental, Mpeg4Viseme::kTHDH},
    {Phone::F, VisemeClass::kLabiodental, Mpeg4Viseme::kFV},
    {Phone::G, VisemeClass::kBack, Mpeg4Viseme::kKG},
    {Phone::HH, VisemeClass::kBack, Mpeg4Viseme::kKG},            // no visible place: as k g
    {Phone::JH, VisemeClass::kPostalveolar, Mpeg4Viseme::kCHJSH},
    {Phone::K, VisemeClass::kBack, Mpeg4Viseme::kKG},
    {Phone::L, VisemeClass::kLateral, Mpeg4Viseme::kNL},
    {Phone::M, VisemeClass::kBilabial, Mpeg4Viseme::kPBM},
    {Phone::N, VisemeClass::kAlveolar, Mpeg4Viseme::kNL},
    {Phone::NG, VisemeClass::kBack, Mpeg4Viseme::kKG},            // velar nasal: as k g, not n
    {Phone::P, VisemeClass::kBilabial, Mpeg4Viseme::kPBM},
    {Phone::R, VisemeClass::kRhotic, Mpeg4Viseme::kR},
    {Phone::S, VisemeClass::kSibilant, Mpeg4Viseme::kSZ},
    {Phone::SH, VisemeClass::kPostalveolar, Mpeg4Viseme::kCHJSH},
    {Phone::T, VisemeClass::kAlveolar, Mpeg4Viseme::kTD},
    {Phone::TH, VisemeClass::kDental, Mpeg4Viseme::kTHDH},
    {Phone::V, VisemeClass::kLabiodental, Mpeg4Viseme::kFV},
    {Phone::W, VisemeClass::kLabialVelar, Mpeg4Viseme::kU},       // rounded glide: as U
    {Phone::Y, VisemeClass::kCloseFront, Mpeg4Viseme::kI},        // palatal glide: as I
    {Phone::Z, VisemeClass::kSibilant, Mpeg4Viseme::kSZ},
    {Phone::ZH, VisemeClass::kPostalveolar, Mpeg4Viseme::kCHJSH},
    {Phone::SIL, VisemeClass::kSilence, Mpeg4Viseme::kNone},
}};

// The class the unit search matches a phone on.
constexpr VisemeClass search_viseme(Phone p) { return kVisemeTable[static_cast<std::size_t>(p)].search_class; }

// The FAP 1 viseme of a phone.
constexpr Mpeg4Viseme mpeg4_viseme(Phone p) { return kVisemeTable[static_cast<std::size_t>(p)].mpeg4; }

// Short stable name of a search class ("bilabial", ...), as in spec/visemes.tsv.
std::string_view viseme_class_name(VisemeClass v);

// A representative phone of a class (its first phone in table order), e.g. for nonsense syllables.
Phone representative_phone(VisemeClass v);

}  // namespace fapcast
