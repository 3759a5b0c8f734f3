#include "fapcast/phonetics/phone_map.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fapcast {

namespace {

// Printable form of a symbol for an error message: control bytes and invalid UTF-8 as \xNN.
std::string printable(std::string_view s) {
  std::string out;
  for (unsigned char c : s) {
    if (c < 0x20 || c == 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

std::string lower_ascii(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

// Length in bytes of the UTF-8 sequence starting at s[i] (1 for an invalid lead byte).
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 1;
  return std::min(n, s.size() - i);
}

}  // namespace

Phone phone_from_espeak(std::string_view mnemonic, std::string_view source) {
  for (const auto& [symbol, phone] : kEspeakMap) {
    if (symbol == mnemonic) return phone;
  }
  throw std::invalid_argument(std::string(source) + ": unknown espeak-ng phoneme '" +
                              printable(mnemonic) + "'");
}

std::vector<Phone> phones_from_ipa(std::string_view ipa, std::string_view source) {
  std::vector<Phone> phones;
  std::size_t i = 0;
  while (i < ipa.size()) {
    const std::string_view rest = ipa.substr(i);
    std::size_t best = 0;
    Phone best_phone = Phone::SIL;
    for (const auto& [symbol, phone] : kIpaMap) {
      if (symbol.size() > best && rest.starts_with(symbol)) {
        best = symbol.size();
        best_phone = phone;
      }
    }
    std::size_t ignored = 0;
    for (std::string_view mark : kIpaIgnored) {
      if (mark.size() > std::max(best, ignored) && rest.starts_with(mark)) ignored = mark.size();
    }
    if (ignored > 0) {
      i += ignored;
    } else if (best > 0) {
      phones.push_back(best_phone);
      i += best;
    } else {
      throw std::invalid_argument(std::string(source) + ": byte " + std::to_string(i) +
                                  ": unknown IPA symbol '" +
                                  printable(rest.substr(0, utf8_length(ipa, i))) + "'");
    }
  }
  return phones;
}

TimitPhone phone_from_timit(std::string_view label, std::string_view source) {
  const std::string lower = lower_ascii(label);
  for (const auto& [symbol, phone] : kTimitMap) {
    if (symbol == lower) return phone;
  }
  throw std::invalid_argument(std::string(source) + ": unknown TIMIT label '" + printable(label) +
                              "'");
}

std::string_view espeak_mnemonic(Phone p) {
  // The first row of kEspeakMap for each phone is its plain, stressable form, except where a
  // better citation form exists (checked by a round-trip test).
  switch (p) {
    case Phone::AA: return "A:";
    case Phone::AH: return "V";
    case Phone::AX: return "@";
    case Phone::ER: return "3:";
    case Phone::IY: return "i:";
    case Phone::AO: return "O:";
    case Phone::UW: return "u:";
    case Phone::L: return "l";
    case Phone::T: return "t";
    case Phone::M: return "m";
    case Phone::N: return "n";
    case Phone::Y: return "j";
    case Phone::K: return "k";
    case Phone::HH: return "h";
    case Phone::R: return "r";
    case Phone::SIL: return "_";
    default: break;
  }
  const auto* row = std::find_if(kEspeakMap.begin(), kEspeakMap.end(),
                                 [p](const auto& entry) { return entry.second == p; });
  return row->first;  // every phone has a row (tested)
}

}  // namespace fapcast
