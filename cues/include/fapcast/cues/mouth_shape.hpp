#pragma once
// The nine mouth shapes of 2D lip sync, named as Rhubarb Lip Sync names them (spec/mouth-cues.md,
// "The mouth shapes"): the six basic shapes A-F, drawn for every character, and the three
// extended shapes G, H and X, which a character's drawings may leave out.
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace fapcast {

enum class MouthShape : std::uint8_t { A, B, C, D, E, F, G, H, X };

inline constexpr std::size_t kMouthShapeCount = 9;

struct MouthShapeInfo {
  MouthShape shape;
  char letter;
  bool extended;           // optional in a character's drawings
  MouthShape basic;        // what is shown when the drawings lack it (itself for A-F)
  std::string_view looks;  // what the drawing shows
};

// One row per shape, in enum order (a test checks the order).
inline constexpr std::array<MouthShapeInfo, kMouthShapeCount> kMouthShapeTable{{
    {MouthShape::A, 'A', false, MouthShape::A, "lips closed with slight pressure: P, B, M"},
    {MouthShape::B, 'B', false, MouthShape::B, "slightly open, teeth clenched: most consonants, the EE of bee"},
    {MouthShape::C, 'C', false, MouthShape::C, "open: EH of men, AE of bat; the step from D towards a closed mouth"},
    {MouthShape::D, 'D', false, MouthShape::D, "wide open: AA of father"},
    {MouthShape::E, 'E', false, MouthShape::E, "slightly rounded: AO of off, ER of bird; the step into and out of F"},
    {MouthShape::F, 'F', false, MouthShape::F, "puckered: UW of you, OW of show, W of way"},
    {MouthShape::G, 'G', true, MouthShape::A, "upper teeth on the lower lip: F, V"},
    {MouthShape::H, 'H', true, MouthShape::C, "tongue raised behind the upper teeth, open about as C: a long L"},
    {MouthShape::X, 'X', true, MouthShape::A, "at rest, lips closed and relaxed: pauses"},
}};

constexpr const MouthShapeInfo& mouth_shape_info(MouthShape s) { return kMouthShapeTable[static_cast<std::size_t>(s)]; }
constexpr char letter(MouthShape s) { return mouth_shape_info(s).letter; }

// The shape written `c` ('A'..'H' or 'X', upper case), or nullopt.
std::optional<MouthShape> mouth_shape_from_letter(char c);

// A set of mouth shapes (one bit per shape).
class MouthShapeSet {
 public:
  constexpr MouthShapeSet() = default;
  constexpr MouthShapeSet(std::initializer_list<MouthShape> shapes) {
    for (MouthShape s : shapes) insert(s);
  }
  static constexpr MouthShapeSet all() { return {MouthShape::A, MouthShape::B, MouthShape::C, MouthShape::D,
                                                 MouthShape::E, MouthShape::F, MouthShape::G, MouthShape::H,
                                                 MouthShape::X}; }
  constexpr void insert(MouthShape s) { bits_ = static_cast<std::uint16_t>(bits_ | bit(s)); }
  constexpr bool contains(MouthShape s) const { return (bits_ & bit(s)) != 0; }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr std::size_t size() const {
    std::size_t n = 0;
    for (std::uint16_t b = bits_; b != 0; b = static_cast<std::uint16_t>(b & (b - 1))) ++n;
    return n;
  }
  friend constexpr bool operator==(MouthShapeSet, MouthShapeSet) = default;

 private:
  static constexpr std::uint16_t bit(MouthShape s) { return static_cast<std::uint16_t>(1u << static_cast<unsigned>(s)); }
  std::uint16_t bits_ = 0;
};

// The shapes a character's drawings have: the six basic ones and the extended ones named in
// `extended` as Rhubarb's --extendedShapes names them ("GHX" all three, "GX", "" none). Nullopt
// when `extended` has a letter other than G, H, X or one twice.
std::optional<MouthShapeSet> drawn_shapes(std::string_view extended);

// The extended shapes of `drawn`, in G, H, X order ("GHX", "X", "").
std::string extended_letters(MouthShapeSet drawn);

// `s` if the drawings have it, else its basic shape (G -> A, H -> C, X -> A).
constexpr MouthShape shown_shape(MouthShape s, MouthShapeSet drawn) {
  return drawn.contains(s) ? s : mouth_shape_info(s).basic;
}

}  // namespace fapcast
