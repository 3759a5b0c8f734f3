#pragma once
// FAP units (FAPU): the face-specific lengths in which FAP values are expressed.
// A FAP value v of a FAP measured in unit U moves its feature point by v * U.
#include <cstdint>
#include <ostream>
#include <string_view>

namespace fapcast {

// The six FAPUs. `kNone` marks the high-level FAPs 1 and 2, which carry indices, not lengths.
enum class Fapu : std::uint8_t {
  kNone,   // FAP 1 (viseme) and FAP 2 (expression)
  kMNS,    // mouth-nose separation / 1024
  kMW,     // mouth width / 1024
  kENS,    // eye-nose separation / 1024
  kES,     // eye separation / 1024
  kIRISD,  // iris diameter / 1024
  kAU,     // angle unit: 1e-5 rad
};

std::string_view to_string(Fapu unit);
std::ostream& operator<<(std::ostream& out, Fapu unit);

// One angle unit, in radians.
inline constexpr double kAngleUnitRad = 1e-5;

}  // namespace fapcast
