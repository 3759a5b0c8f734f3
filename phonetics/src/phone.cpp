#include "fapcast/phonetics/phone.hpp"

#include <stdexcept>
#include <string>

namespace fapcast {

namespace {

char to_upper_ascii(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

}  // namespace

StressedPhone parse_arpabet(std::string_view symbol, std::string_view source) {
  std::string upper;
  upper.reserve(symbol.size());
  for (char c : symbol) upper.push_back(to_upper_ascii(c));
  std::optional<Stress> stress;
  if (!upper.empty() && upper.back() >= '0' && upper.back() <= '2') {
    stress = static_cast<Stress>(upper.back() - '0');
    upper.pop_back();
  }
  // CMUdict has no AX: it spells the schwa AH0 (Festival's CMU lexicon and TIMIT write AX).
  if (upper == "AH" && stress == Stress::kNone) return {Phone::AX, stress};
  for (const PhoneInfo& row : kPhoneTable) {
    if (row.arpabet == upper && !(stress && row.phone == Phone::SIL)) return {row.phone, stress};
  }
  throw std::invalid_argument(std::string(source) + ": unknown ARPAbet phone '" +
                              std::string(symbol) + "'");
}

std::ostream& operator<<(std::ostream& out, Phone p) { return out << arpabet(p); }

}  // namespace fapcast
