// The label sets real alignment files use, through the phone map: each set's own symbols, the
// silences and noises every set shares, Gentle's position tags, joins and compounds.
#include "fapcast/phonetics/label_sets.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

Phone one(LabelSet set, std::string_view label) {
  const auto m = map_label(set, label);
  EXPECT_TRUE(m) << label;
  if (!m) return Phone::SIL;
  EXPECT_EQ(m->kind, LabelKind::phone) << label;
  EXPECT_EQ(m->phones.size(), 1u) << label;
  return m->phones.at(0);
}

TEST(LabelSets, NamesRoundTrip) {
  for (LabelSet s : kLabelSets) EXPECT_EQ(label_set_from_name(label_set_name(s)), s);
  EXPECT_FALSE(label_set_from_name("xsampa"));
}

TEST(LabelSets, SilencesAndNoisesAreFoundNotForcedOntoPhones) {
  for (std::string_view s : {"", "sil", "sp", "pau", "h#", "H#", "#", "<p:>", "<p>", "epi"}) {
    for (LabelSet set : kLabelSets) {
      const auto m = map_label(set, s);
      ASSERT_TRUE(m) << s;
      EXPECT_EQ(m->kind, LabelKind::silence) << s;
      EXPECT_TRUE(m->phones.empty());
    }
  }
  for (std::string_view s : {"spn", "oov", "<usb>", "<nib>", "<unk>"}) {
    EXPECT_EQ(map_label(LabelSet::arpabet, s)->kind, LabelKind::noise) << s;
  }
  EXPECT_EQ(map_label(LabelSet::arpabet, "oov_S")->kind, LabelKind::noise);  // Gentle
}

TEST(LabelSets, Arpabet) {
  EXPECT_EQ(one(LabelSet::arpabet, "AH0"), Phone::AX);  // CMUdict's schwa
  EXPECT_EQ(one(LabelSet::arpabet, "AH1"), Phone::AH);
  EXPECT_EQ(one(LabelSet::arpabet, "ah_I"), Phone::AH);  // Gentle's word-position tag
  EXPECT_EQ(one(LabelSet::arpabet, "ax"), Phone::AX);    // Festival's radio set
  EXPECT_EQ(one(LabelSet::arpabet, "jh_B"), Phone::JH);
  EXPECT_FALSE(map_label(LabelSet::arpabet, "PT"));
  EXPECT_FALSE(map_label(LabelSet::arpabet, "dcl"));
}

TEST(LabelSets, TimitClosuresJoinTheirRelease) {
  const auto dcl = map_label(LabelSet::timit, "dcl");
  ASSERT_TRUE(dcl);
  EXPECT_EQ(dcl->join, LabelJoin::with_next);
  EXPECT_EQ(dcl->phones.at(0), Phone::D);
  EXPECT_EQ(one(LabelSet::timit, "ax-h"), Phone::AX);
  EXPECT_EQ(one(LabelSet::timit, "ah"), Phone::AH);
  EXPECT_EQ(one(LabelSet::timit, "hv"), Phone::HH);
}

TEST(LabelSets, IpaOfMfaAndPraat) {
  EXPECT_EQ(one(LabelSet::ipa, "aj"), Phone::AY);
  EXPECT_EQ(one(LabelSet::ipa, "tʲ"), Phone::T);
  EXPECT_EQ(one(LabelSet::ipa, "ɫ"), Phone::L);
  EXPECT_EQ(one(LabelSet::ipa, "tʰ"), Phone::T);
  EXPECT_EQ(one(LabelSet::ipa, "ð"), Phone::DH);
  EXPECT_EQ(one(LabelSet::ipa, "ɚ"), Phone::ER);
  EXPECT_FALSE(map_label(LabelSet::ipa, "ok"));  // two phones: a word, not a phone label
}

TEST(LabelSets, SampaOfWebMaus) {
  EXPECT_EQ(one(LabelSet::sampa, "3`"), Phone::ER);
  EXPECT_EQ(one(LabelSet::sampa, "eI"), Phone::EY);
  EXPECT_EQ(one(LabelSet::sampa, "R"), Phone::R);
  EXPECT_EQ(one(LabelSet::sampa, "{"), Phone::AE);
  EXPECT_EQ(one(LabelSet::sampa, "C"), Phone::HH);  // German ich-Laut
  const auto ts = map_label(LabelSet::sampa, "ts");
  ASSERT_TRUE(ts);
  EXPECT_EQ(ts->phones, (std::vector<Phone>{Phone::T, Phone::S}));
}

TEST(LabelSets, EmuAeAspirationAndCompounds) {
  const auto h = map_label(LabelSet::emu_ae, "H");
  ASSERT_TRUE(h);
  EXPECT_EQ(h->join, LabelJoin::with_previous);
  const auto db = map_label(LabelSet::emu_ae, "db");
  ASSERT_TRUE(db);
  EXPECT_EQ(db->phones, (std::vector<Phone>{Phone::D, Phone::B}));
  EXPECT_EQ(one(LabelSet::emu_ae, "@u"), Phone::OW);
  EXPECT_EQ(one(LabelSet::emu_ae, "A"), Phone::AE);
  EXPECT_FALSE(map_label(LabelSet::emu_ae, "3`"));
}

TEST(LabelSets, MochaTimitByLexicalSet) {
  EXPECT_EQ(one(LabelSet::mocha, "@"), Phone::AX);
  EXPECT_EQ(one(LabelSet::mocha, "@@"), Phone::ER);
  EXPECT_EQ(one(LabelSet::mocha, "uh"), Phone::AH);  // strut, not ARPAbet's UH (foot)
  EXPECT_EQ(one(LabelSet::mocha, "u"), Phone::UH);
  EXPECT_EQ(one(LabelSet::mocha, "ii"), Phone::IY);
  EXPECT_EQ(one(LabelSet::mocha, "i"), Phone::IH);
  EXPECT_EQ(one(LabelSet::mocha, "o"), Phone::AO);  // lot is rounded in southern British English
  EXPECT_EQ(one(LabelSet::mocha, "y"), Phone::Y);
  EXPECT_EQ(one(LabelSet::mocha, "dh"), Phone::DH);
  EXPECT_EQ(map_label(LabelSet::mocha, "breath")->kind, LabelKind::breath);  // an inhalation, not a phone
  EXPECT_FALSE(map_label(LabelSet::mocha, "AH0"));  // ARPAbet is not MOCHA's
  EXPECT_FALSE(map_label(LabelSet::arpabet, "@"));
}

}  // namespace
}  // namespace fapcast
