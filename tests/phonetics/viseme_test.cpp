// Viseme tables: every phone has both visemes, every class is used, and spec/visemes.tsv
// says exactly what the C++ table says.
#include "fapcast/phonetics/viseme.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace fapcast {
namespace {

TEST(VisemeTable, OneRowPerPhoneInOrder) {
  for (std::size_t i = 0; i < kVisemeTable.size(); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(kVisemeTable[i].phone), i);
    EXPECT_LT(static_cast<std::size_t>(kVisemeTable[i].search_class), kVisemeClassCount);
    EXPECT_LT(static_cast<std::size_t>(kVisemeTable[i].mpeg4), kMpeg4VisemeCount);
  }
}

TEST(VisemeTable, EverySearchClassAndEveryMpeg4VisemeIsUsed) {
  std::set<VisemeClass> classes;
  std::set<Mpeg4Viseme> mpeg4;
  for (const auto& row : kVisemeTable) {
    classes.insert(row.search_class);
    mpeg4.insert(row.mpeg4);
  }
  EXPECT_EQ(classes.size(), kVisemeClassCount);
  EXPECT_EQ(mpeg4.size(), kMpeg4VisemeCount);
}

TEST(VisemeTable, OnlySilenceHasNoVisemeAndBilabialsShareOne) {
  for (const auto& row : kVisemeTable) {
    EXPECT_EQ(row.mpeg4 == Mpeg4Viseme::kNone, row.phone == Phone::SIL) << arpabet(row.phone);
    EXPECT_EQ(row.search_class == VisemeClass::kSilence, row.phone == Phone::SIL);
  }
  for (Phone p : {Phone::P, Phone::B, Phone::M}) {
    EXPECT_EQ(search_viseme(p), VisemeClass::kBilabial);
    EXPECT_EQ(mpeg4_viseme(p), Mpeg4Viseme::kPBM);
  }
}

TEST(VisemeTable, SearchClassesNeverMixRoundedAndSpreadVowels) {
  // A class is one lip shape: its vowels agree on rounding at the target.
  for (std::size_t c = 0; c < kVisemeClassCount; ++c) {
    std::set<bool> rounding;
    for (const auto& row : kVisemeTable) {
      if (static_cast<std::size_t>(row.search_class) == c && is_vowel(row.phone)) {
        rounding.insert(phone_info(row.phone).rounded);
      }
    }
    EXPECT_LE(rounding.size(), 1u) << viseme_class_name(static_cast<VisemeClass>(c));
  }
}

TEST(VisemeTable, RepresentativeBelongsToItsClass) {
  for (std::size_t c = 0; c < kVisemeClassCount; ++c) {
    const auto v = static_cast<VisemeClass>(c);
    EXPECT_EQ(search_viseme(representative_phone(v)), v);
  }
}

TEST(VisemeSpec, SpecTsvMatchesTheTable) {
  std::ifstream in(FAPCAST_SOURCE_DIR "/spec/visemes.tsv");
  ASSERT_TRUE(in) << "spec/visemes.tsv missing";
  std::string line;
  std::size_t row = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string phone, name;
    int index = -1, mpeg4 = -1;
    ASSERT_TRUE(fields >> phone >> name >> index >> mpeg4) << line;
    ASSERT_LT(row, kVisemeTable.size());
    const VisemeRow& r = kVisemeTable[row++];
    EXPECT_EQ(phone, arpabet(r.phone));
    EXPECT_EQ(name, viseme_class_name(r.search_class)) << phone;
    EXPECT_EQ(index, static_cast<int>(r.search_class)) << phone;
    EXPECT_EQ(mpeg4, static_cast<int>(r.mpeg4)) << phone;
  }
  EXPECT_EQ(row, kVisemeTable.size());
}

}  // namespace
}  // namespace fapcast
