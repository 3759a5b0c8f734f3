#include "fapcast/phonetics/viseme.hpp"

#include <stdexcept>

namespace fapcast {

namespace {

// Names in VisemeClass order.
constexpr std::array<std::string_view, kVisemeClassCount> kClassNames{
    "silence",      "bilabial",     "labiodental",      "dental",          "alveolar",
    "sibilant",     "lateral",      "postalveolar",     "rhotic",          "back",
    "labial_velar", "close_front",  "near_close_front", "mid_front",       "open_front",
    "open_unrounded", "open_mid_rounded", "mid_rounded", "near_close_rounded", "close_rounded",
    "schwa"};

}  // namespace

std::string_view viseme_class_name(VisemeClass v) {
  return kClassNames.at(static_cast<std::size_t>(v));
}

Phone representative_phone(VisemeClass v) {
  for (const VisemeRow& row : kVisemeTable) {
    if (row.search_class == v) return row.phone;
  }
  throw std::logic_error("viseme class without phones");  // excluded by a test
}

}  // namespace fapcast
