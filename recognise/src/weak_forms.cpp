#include "weak_forms.hpp"

#include <sstream>
#include <string>

namespace fapcast {

namespace {

// One word's weak forms: `forms` always; `linking` (the form with a linking r) before a vowel only.
struct WeakForm {
  std::string_view word;
  std::string_view forms;    // ARPAbet, forms separated by '|'
  std::string_view linking;  // ARPAbet, or empty
};

// The function words of P. Roach, "English Phonetics and Phonology" (4th ed., CUP 2009),
// chapter 12 ("Weak forms"), with their weak forms transcribed into ARPAbet. Forms CMUdict
// already has (the DH AH, to T AH, of AH V, was W AH Z ...) are listed too: the aligner adds only
// those a word lacks.
constexpr WeakForm kWeakForms[] = {
    {"a", "AH", ""},
    {"am", "AH M|M", ""},
    {"an", "AH N", ""},
    {"and", "AH N D|AH N|N", ""},
    {"are", "AH", "AH R"},
    {"as", "AH Z", ""},
    {"at", "AH T", ""},
    {"but", "B AH T", ""},
    {"can", "K AH N|K N", ""},
    {"could", "K AH D", ""},
    {"do", "D AH", ""},
    {"does", "D AH Z", ""},
    {"for", "F AH", "F AH R"},
    {"from", "F R AH M", ""},
    {"had", "HH AH D|AH D", ""},
    {"has", "HH AH Z|AH Z", ""},
    {"have", "HH AH V|AH V", ""},
    {"he", "IY", ""},
    {"her", "HH AH|AH", "HH AH R|AH R"},
    {"him", "IH M", ""},
    {"his", "IH Z", ""},
    {"must", "M AH S T|M AH S", ""},
    {"of", "AH V", ""},
    {"shall", "SH AH L|SH L", ""},
    {"should", "SH AH D", ""},
    {"some", "S AH M", ""},
    {"than", "DH AH N", ""},
    {"that", "DH AH T", ""},
    {"the", "DH AH", ""},
    {"them", "DH AH M", ""},
    {"there", "DH AH", "DH AH R"},
    {"to", "T AH", ""},
    {"us", "AH S", ""},
    {"was", "W AH Z", ""},
    {"were", "W AH", "W AH R"},
};

void append_forms(std::string_view forms, std::vector<std::vector<Phone>>& out) {
  std::string all(forms);
  for (char& c : all)
    if (c == '|') c = '\n';
  std::istringstream lines(all);
  for (std::string line; std::getline(lines, line);) {
    std::vector<Phone> form;
    std::istringstream in(line);
    for (std::string s; in >> s;) form.push_back(parse_arpabet(s, "weak-form table").phone);
    out.push_back(std::move(form));
  }
}

}  // namespace

std::vector<std::vector<Phone>> weak_forms(std::string_view key, bool before_vowel) {
  std::vector<std::vector<Phone>> out;
  for (const WeakForm& w : kWeakForms) {
    if (w.word != key) continue;
    append_forms(w.forms, out);
    if (before_vowel && !w.linking.empty()) append_forms(w.linking, out);
  }
  return out;
}

}  // namespace fapcast
