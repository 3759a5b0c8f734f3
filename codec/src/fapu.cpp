#include "fapcast/codec/fapu.hpp"

namespace fapcast {

std::string_view to_string(Fapu unit) {
  switch (unit) {
    case Fapu::kNone: return "none";
    case Fapu::kMNS: return "MNS";
    case Fapu::kMW: return "MW";
    case Fapu::kENS: return "ENS";
    case Fapu::kES: return "ES";
    case Fapu::kIRISD: return "IRISD";
    case Fapu::kAU: return "AU";
  }
  return "?";
}

std::ostream& operator<<(std::ostream& out, Fapu unit) { return out << to_string(unit); }

}  // namespace fapcast
