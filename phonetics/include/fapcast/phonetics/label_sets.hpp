#pragma once
// The symbol sets real alignment files label phones in, each read through the phone map into
// fapcast's phone set (spec/phones.md "Label sets"). A label is a phone (or two, for compound
// labels), silence, or noise: silences and noises are found and reported, never forced onto a
// phone; both are animated as rest.
#include "fapcast/phonetics/phone.hpp"

#include <optional>
#include <string_view>
#include <vector>

namespace fapcast {

enum class LabelSet {
  arpabet,  // CMUdict / MFA english_us_arpa / Gentle ("AH0", "ah_I"), Festival's radio set ("ax")
  timit,    // the 61 TIMIT labels (h#, dcl, ax-h ...), folded to 39, and ARPAbet mixed with them
  ipa,      // IPA (MFA's IPA sets, Praat's IPA chart, espeak-ng --ipa)
  sampa,    // SAMPA / X-SAMPA as BAS WebMAUS writes it (English and German inventories)
  emu_ae,   // the EMU demo database "ae" (Australian English SAMPA with compound labels)
  mocha,    // MOCHA-TIMIT's labels (southern British English: @ @@ ii i uh oo ou ..., breath)
};
inline constexpr LabelSet kLabelSets[] = {LabelSet::arpabet, LabelSet::timit, LabelSet::ipa, LabelSet::sampa,
                                          LabelSet::emu_ae, LabelSet::mocha};
std::string_view label_set_name(LabelSet set);  // "arpabet", "timit", "ipa", "sampa", "emu-ae", "mocha"
std::optional<LabelSet> label_set_from_name(std::string_view name);

// breath: an audible inhalation (MOCHA's "breath"). Not a phone of the words: alignments and
// boundary comparisons read it as a pause; the animation shows it as an inhalation, the mouth open
// until speech starts (alignment_phones.hpp, kInhalation).
enum class LabelKind { phone, silence, noise, breath };

// How a segment joins its neighbour: a TIMIT closure with the release after it, an EMU
// aspiration ("H") with the stop before it.
enum class LabelJoin { none, with_next, with_previous };

struct MappedLabel {
  LabelKind kind = LabelKind::silence;
  std::vector<Phone> phones;  // 1 or 2 for kind == phone (compounds split the segment evenly)
  LabelJoin join = LabelJoin::none;
};

// Silence and noise labels every set shares: "", sil, sp, pau, h#, H#, #, <p:>, <p>, epi
// (silence); spn, oov, <usb>, <nib>, <unk>, <nsp> (noise). nullopt when `label` is neither.
std::optional<LabelKind> common_non_phone(std::string_view label);

// `label` read in `set`; nullopt when the set has no such symbol.
std::optional<MappedLabel> map_label(LabelSet set, std::string_view label);

}  // namespace fapcast
