#include "fapcast/phonetics/label_sets.hpp"

#include "fapcast/phonetics/phone_map.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace fapcast {
namespace {

struct Row {
  std::string_view symbol;
  Phone first;
  std::optional<Phone> second = std::nullopt;
  LabelJoin join = LabelJoin::none;
};

// SAMPA / X-SAMPA as BAS WebMAUS writes it (its English and German inventories). X-SAMPA's
// r-coloured schwa "@`" and "3`" are ER; "R" and "r\" are the English approximant; German vowels
// go to the nearest English vowel by height, backness and rounding (6 = ɐ, 9 = œ, 2: = ø:, y: = y:).
constexpr auto kSampa = std::to_array<Row>({
    {"i:", Phone::IY}, {"I", Phone::IH}, {"e", Phone::EH}, {"e:", Phone::EY}, {"E", Phone::EH}, {"E:", Phone::EH},
    {"{", Phone::AE}, {"a", Phone::AE}, {"a:", Phone::AA}, {"A:", Phone::AA}, {"A", Phone::AA}, {"Q", Phone::AA},
    {"V", Phone::AH}, {"@", Phone::AX}, {"6", Phone::AX}, {"3:", Phone::ER}, {"3`", Phone::ER}, {"@`", Phone::ER},
    {"3", Phone::ER}, {"O:", Phone::AO}, {"O", Phone::AO}, {"o:", Phone::OW}, {"o", Phone::OW}, {"U", Phone::UH},
    {"u:", Phone::UW}, {"u", Phone::UW}, {"y:", Phone::UW}, {"Y", Phone::UH}, {"2:", Phone::ER}, {"9", Phone::ER},
    {"eI", Phone::EY}, {"aI", Phone::AY}, {"OI", Phone::OY}, {"OY", Phone::OY}, {"@U", Phone::OW}, {"oU", Phone::OW},
    {"aU", Phone::AW}, {"I@", Phone::IY}, {"E@", Phone::EH}, {"U@", Phone::UH},
    {"p", Phone::P}, {"b", Phone::B}, {"t", Phone::T}, {"d", Phone::D}, {"k", Phone::K}, {"g", Phone::G},
    {"?", Phone::T}, {"4", Phone::T}, {"f", Phone::F}, {"v", Phone::V}, {"T", Phone::TH}, {"D", Phone::DH},
    {"s", Phone::S}, {"z", Phone::Z}, {"S", Phone::SH}, {"Z", Phone::ZH}, {"h", Phone::HH}, {"C", Phone::HH},
    {"x", Phone::K}, {"tS", Phone::CH}, {"dZ", Phone::JH}, {"pf", Phone::P, Phone::F}, {"ts", Phone::T, Phone::S},
    {"m", Phone::M}, {"n", Phone::N}, {"N", Phone::NG}, {"l", Phone::L}, {"r", Phone::R}, {"R", Phone::R},
    {"r\\", Phone::R}, {"j", Phone::Y}, {"w", Phone::W}, {"m=", Phone::M}, {"n=", Phone::N}, {"l=", Phone::L},
});

// The EMU demo database "ae" (Australian English, msajc*): SAMPA with its own vowel spellings
// (A = trap, O = lot, rounded in Australian English, @u = goat, @: = nurse, ai ei oi au) and
// compound labels for merged segments: "H" is a stop's aspiration (joined to the stop before
// it), "db pt kt zs" two consonants in one segment, "dH" a released d, "NH" a velar nasal's
// release, "Om On Or Ow" the lot vowel coloured by the consonant that follows it.
constexpr auto kEmuAe = std::to_array<Row>({
    {"i:", Phone::IY}, {"I", Phone::IH}, {"e", Phone::EH}, {"E", Phone::EH}, {"A", Phone::AE}, {"a:", Phone::AA},
    {"V", Phone::AH}, {"@", Phone::AX}, {"@:", Phone::ER}, {"3:", Phone::ER}, {"O", Phone::AO}, {"o:", Phone::AO},
    {"U", Phone::UH}, {"u:", Phone::UW}, {"ai", Phone::AY}, {"ei", Phone::EY}, {"oi", Phone::OY}, {"au", Phone::AW},
    {"@u", Phone::OW}, {"I@", Phone::IY}, {"E@", Phone::EH}, {"U@", Phone::UH},
    {"p", Phone::P}, {"b", Phone::B}, {"t", Phone::T}, {"d", Phone::D}, {"k", Phone::K}, {"g", Phone::G},
    {"f", Phone::F}, {"v", Phone::V}, {"T", Phone::TH}, {"D", Phone::DH}, {"s", Phone::S}, {"z", Phone::Z},
    {"S", Phone::SH}, {"Z", Phone::ZH}, {"h", Phone::HH}, {"tS", Phone::CH}, {"dZ", Phone::JH}, {"m", Phone::M},
    {"n", Phone::N}, {"N", Phone::NG}, {"l", Phone::L}, {"r", Phone::R}, {"j", Phone::Y}, {"w", Phone::W},
    {"H", Phone::HH, std::nullopt, LabelJoin::with_previous},
    {"db", Phone::D, Phone::B}, {"pt", Phone::P, Phone::T}, {"kt", Phone::K, Phone::T}, {"zs", Phone::Z, Phone::S},
    {"dH", Phone::D}, {"NH", Phone::NG}, {"Om", Phone::AO}, {"On", Phone::AO}, {"Or", Phone::AO}, {"Ow", Phone::AO},
});

// MOCHA-TIMIT's labels (its southern British speakers; the symbols of the lexical sets they
// stand for): @ = schwa, @@ = nurse, a = trap, aa = bath/start, uh = strut, o = lot (rounded in
// southern British English, so AO, not AA), oo = thought, ou = goat, i = kit, ii = fleece, iy =
// the happY vowel, u = foot, uu = goose, e@ i@ u@ = square near cure; consonants as ARPAbet in
// lower case ("y" = yes). "breath" is an inhalation (LabelKind::breath, mapped in map_label).
constexpr auto kMocha = std::to_array<Row>({
    {"@", Phone::AX}, {"@@", Phone::ER}, {"a", Phone::AE}, {"aa", Phone::AA}, {"uh", Phone::AH}, {"o", Phone::AO},
    {"oo", Phone::AO}, {"ou", Phone::OW}, {"i", Phone::IH}, {"ii", Phone::IY}, {"iy", Phone::IY}, {"u", Phone::UH},
    {"uu", Phone::UW}, {"e", Phone::EH}, {"ei", Phone::EY}, {"ai", Phone::AY}, {"au", Phone::AW}, {"oi", Phone::OY},
    {"e@", Phone::EH}, {"i@", Phone::IY}, {"u@", Phone::UH},
    {"p", Phone::P}, {"b", Phone::B}, {"t", Phone::T}, {"d", Phone::D}, {"k", Phone::K}, {"g", Phone::G},
    {"f", Phone::F}, {"v", Phone::V}, {"th", Phone::TH}, {"dh", Phone::DH}, {"s", Phone::S}, {"z", Phone::Z},
    {"sh", Phone::SH}, {"zh", Phone::ZH}, {"h", Phone::HH}, {"ch", Phone::CH}, {"jh", Phone::JH}, {"m", Phone::M},
    {"n", Phone::N}, {"ng", Phone::NG}, {"l", Phone::L}, {"r", Phone::R}, {"w", Phone::W}, {"y", Phone::Y},
});

template <std::size_t N>
std::optional<MappedLabel> from_table(const std::array<Row, N>& table, std::string_view label) {
  for (const Row& r : table) {
    if (r.symbol != label) continue;
    MappedLabel m{LabelKind::phone, {r.first}, r.join};
    if (r.second) m.phones.push_back(*r.second);
    return m;
  }
  return std::nullopt;
}

std::string upper_ascii(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return out;
}

}  // namespace

std::string_view label_set_name(LabelSet set) {
  switch (set) {
    case LabelSet::arpabet: return "arpabet";
    case LabelSet::timit: return "timit";
    case LabelSet::ipa: return "ipa";
    case LabelSet::sampa: return "sampa";
    case LabelSet::emu_ae: return "emu-ae";
    case LabelSet::mocha: return "mocha";
  }
  return "?";
}

std::optional<LabelSet> label_set_from_name(std::string_view name) {
  for (LabelSet s : kLabelSets) {
    if (label_set_name(s) == name) return s;
  }
  return std::nullopt;
}

std::optional<LabelKind> common_non_phone(std::string_view label) {
  static constexpr std::array<std::string_view, 13> kSilence{"", "sil", "SIL", "sp", "SP", "pau", "PAU", "h#", "H#",
                                                             "#", "<p:>", "<p>", "epi"};
  static constexpr std::array<std::string_view, 8> kNoise{"spn", "SPN", "oov", "<usb>", "<nib>", "<unk>", "<nsp>",
                                                          "<noise>"};
  for (auto s : kSilence) {
    if (label == s) return LabelKind::silence;
  }
  for (auto s : kNoise) {
    if (label == s) return LabelKind::noise;
  }
  return std::nullopt;
}

std::optional<MappedLabel> map_label(LabelSet set, std::string_view label) {
  if (set == LabelSet::arpabet && label.size() > 2 && label[label.size() - 2] == '_' &&
      std::string_view("BIES").find(label.back()) != std::string_view::npos) {
    label.remove_suffix(2);  // Gentle's word-position tag: "ah_I", "oov_S"
  }
  if (auto k = common_non_phone(label)) return MappedLabel{*k, {}, LabelJoin::none};
  try {
    switch (set) {
      case LabelSet::arpabet: {
        const std::string up = upper_ascii(label);
        const StressedPhone p = parse_arpabet(up, "label");
        if (p.phone == Phone::SIL) return MappedLabel{LabelKind::silence, {}, LabelJoin::none};
        return MappedLabel{LabelKind::phone, {p.phone}, LabelJoin::none};
      }
      case LabelSet::timit: {
        // TIMIT's labels, and the ARPAbet that TIMIT-trained aligners mix with them.
        TimitPhone t{Phone::SIL, false};
        try {
          t = phone_from_timit(label, "label");
        } catch (const std::invalid_argument&) {
          t = {parse_arpabet(label, "label").phone, false};
        }
        if (t.phone == Phone::SIL) return MappedLabel{LabelKind::silence, {}, LabelJoin::none};
        return MappedLabel{LabelKind::phone, {t.phone}, t.closure ? LabelJoin::with_next : LabelJoin::none};
      }
      case LabelSet::ipa: {
        std::vector<Phone> phones = phones_from_ipa(label, "label");
        if (phones.size() != 1) return std::nullopt;  // a word or a transcription, not one phone
        return MappedLabel{LabelKind::phone, std::move(phones), LabelJoin::none};
      }
      case LabelSet::sampa: return from_table(kSampa, label);
      case LabelSet::emu_ae: return from_table(kEmuAe, label);
      case LabelSet::mocha:
        if (label == "breath") return MappedLabel{LabelKind::breath, {}, LabelJoin::none};
        return from_table(kMocha, label);
    }
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace fapcast
