#include "weak_forms.hpp"

namespace fapcast {

namespace {

struct WeakForm {
  std::string_view word;
  std::string_view phones;  // ARPAbet
  bool linking_r;           // the form with a linking r: before a vowel only
};

// The function words of P. Roach, "English Phonetics and Phonology" (4th ed., CUP 2009),
// chapter 12 ("Weak forms"), with their weak forms transcribed into ARPAbet. Forms CMUdict
// already has (the DH AH, to T AH, of AH V, was W AH Z ...) are listed too: the aligner adds only
// those a word lacks.
constexpr WeakForm kWeakForms[] = {
    {"a", "AH", false},
    {"am", "AH M", false},
    {"am", "M", false},
    {"an", "AH N", false},
    {"and", "AH N D", false},
    {"and", "AH N", false},
    {"and", "N", false},
    {"are", "AH", false},
    {"are", "AH R", true},
    {"as", "AH Z", false},
    {"at", "AH T", false},
    {"but", "B AH T", false},
    {"can", "K AH N", false},
    {"can", "K N", false},
    {"could", "K AH D", false},
    {"do", "D AH", false},
    {"does", "D AH Z", false},
    {"for", "F AH", false},
    {"for", "F AH R", true},
    {"from", "F R AH M", false},
    {"had", "HH AH D", false},
    {"had", "AH D", false},
    {"has", "HH AH Z", false},
    {"has", "AH Z", false},
    {"have", "HH AH V", false},
    {"have", "AH V", false},
    {"he", "IY", false},
    {"her", "HH AH", false},
    {"her", "AH", false},
    {"her", "HH AH R", true},
    {"her", "AH R", true},
    {"him", "IH M", false},
    {"his", "IH Z", false},
    {"must", "M AH S T", false},
    {"must", "M AH S", false},
    {"of", "AH V", false},
    {"shall", "SH AH L", false},
    {"shall", "SH L", false},
    {"should", "SH AH D", false},
    {"some", "S AH M", false},
    {"than", "DH AH N", false},
    {"that", "DH AH T", false},
    {"the", "DH AH", false},
    {"them", "DH AH M", false},
    {"there", "DH AH", false},
    {"there", "DH AH R", true},
    {"to", "T AH", false},
    {"us", "AH S", false},
    {"was", "W AH Z", false},
    {"were", "W AH", false},
    {"were", "W AH R", true},
};

}  // namespace

std::vector<std::string_view> weak_forms(std::string_view key, bool before_vowel) {
  std::vector<std::string_view> out;
  for (const WeakForm& w : kWeakForms)
    if (w.word == key && (before_vowel || !w.linking_r)) out.push_back(w.phones);
  return out;
}

}  // namespace fapcast
