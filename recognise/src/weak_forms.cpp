#include "weak_forms.hpp"

namespace fapcast {

namespace {

struct WeakForm {
  std::string_view word;
  std::string_view phones;  // ARPAbet
  bool linking_r;           // the form with a linking r: before a vowel only
};

// The function words of P. Roach, "English Phonetics and Phonology" (4th ed., CUP 2009),
// chapter 12 ("Weak forms"), with their weak forms transcribed into ARPAbet, the schwa as AX. Forms
// CMUdict already has (the DH AH, to T AH, of AH V, was W AH Z ...) are listed too: the aligner adds
// only those a word lacks, and names the schwa of those it has.
constexpr WeakForm kWeakForms[] = {
    {"a", "AX", false},
    {"am", "AX M", false},
    {"am", "M", false},
    {"an", "AX N", false},
    {"and", "AX N D", false},
    {"and", "AX N", false},
    {"and", "N", false},
    {"are", "AX", false},
    {"are", "AX R", true},
    {"as", "AX Z", false},
    {"at", "AX T", false},
    {"but", "B AX T", false},
    {"can", "K AX N", false},
    {"can", "K N", false},
    {"could", "K AX D", false},
    {"do", "D AX", false},
    {"does", "D AX Z", false},
    {"for", "F AX", false},
    {"for", "F AX R", true},
    {"from", "F R AX M", false},
    {"had", "HH AX D", false},
    {"had", "AX D", false},
    {"has", "HH AX Z", false},
    {"has", "AX Z", false},
    {"have", "HH AX V", false},
    {"have", "AX V", false},
    {"he", "IY", false},
    {"her", "HH AX", false},
    {"her", "AX", false},
    {"her", "HH AX R", true},
    {"her", "AX R", true},
    {"him", "IH M", false},
    {"his", "IH Z", false},
    {"must", "M AX S T", false},
    {"must", "M AX S", false},
    {"of", "AX V", false},
    {"shall", "SH AX L", false},
    {"shall", "SH L", false},
    {"should", "SH AX D", false},
    {"some", "S AX M", false},
    {"than", "DH AX N", false},
    {"that", "DH AX T", false},
    {"the", "DH AX", false},
    {"them", "DH AX M", false},
    {"there", "DH AX", false},
    {"there", "DH AX R", true},
    {"to", "T AX", false},
    {"us", "AX S", false},
    {"was", "W AX Z", false},
    {"were", "W AX", false},
    {"were", "W AX R", true},
};

}  // namespace

std::vector<std::string_view> weak_forms(std::string_view key, bool before_vowel) {
  std::vector<std::string_view> out;
  for (const WeakForm& w : kWeakForms)
    if (w.word == key && (before_vowel || !w.linking_r)) out.push_back(w.phones);
  return out;
}

}  // namespace fapcast
