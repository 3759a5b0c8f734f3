// The phone set and its maps: table order, parsing, every map total and unambiguous, errors
// that name the symbol and its source.
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/phonetics/phone_map.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace fapcast {
namespace {

TEST(PhoneTable, RowsAreInEnumOrderWithUniqueNames) {
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < kPhoneTable.size(); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(kPhoneTable[i].phone), i) << kPhoneTable[i].arpabet;
    EXPECT_TRUE(names.insert(kPhoneTable[i].arpabet).second) << kPhoneTable[i].arpabet;
  }
  EXPECT_EQ(kPhoneTable.back().phone, Phone::SIL);
}

TEST(PhoneTable, ThirtyNineCmudictPhonesSchwaAndSilence) {
  int vowels = 0;
  for (const auto& row : kPhoneTable) vowels += is_vowel(row.phone) ? 1 : 0;
  EXPECT_EQ(vowels, 16);
  EXPECT_EQ(kPhoneTable.size(), 41u);
}

TEST(PhoneTable, ClosingPhonesAreStopsAffricatesAndM) {
  std::set<std::string_view> closing;
  for (const auto& row : kPhoneTable) if (has_closure(row.phone)) closing.insert(row.arpabet);
  EXPECT_EQ(closing, (std::set<std::string_view>{"B", "CH", "D", "G", "JH", "K", "M", "P", "T"}));
}

struct ArpabetCase { const char* symbol; Phone phone; std::optional<Stress> stress; };
class ParseArpabet : public testing::TestWithParam<ArpabetCase> {};
TEST_P(ParseArpabet, ParsesPhoneAndStress) {
  const auto& c = GetParam();
  EXPECT_EQ(parse_arpabet(c.symbol, "test"), (StressedPhone{c.phone, c.stress}));
}
INSTANTIATE_TEST_SUITE_P(Cases, ParseArpabet, testing::Values(
    ArpabetCase{"AA1", Phone::AA, Stress::kPrimary}, ArpabetCase{"ah0", Phone::AX, Stress::kNone}, ArpabetCase{"AH1", Phone::AH, Stress::kPrimary},
    ArpabetCase{"ER2", Phone::ER, Stress::kSecondary}, ArpabetCase{"zh", Phone::ZH, std::nullopt},
    ArpabetCase{"ax", Phone::AX, std::nullopt}, ArpabetCase{"AH", Phone::AH, std::nullopt}, ArpabetCase{"SIL", Phone::SIL, std::nullopt}));

TEST(ParseArpabet, RoundTripsEveryPhoneName) {
  for (const auto& row : kPhoneTable) EXPECT_EQ(parse_arpabet(row.arpabet, "t").phone, row.phone);
}

TEST(ParseArpabet, UnknownSymbolNamesSymbolAndSource) {
  for (const char* bad : {"", "Q", "AA3", "SIL1", "A A", "1"}) {
    try {
      parse_arpabet(bad, "dict.txt:7");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), std::string("dict.txt:7: unknown ARPAbet phone '") + bad + "'");
    }
  }
}

TEST(EspeakMap, SymbolsAreUniqueAndEveryPhoneIsReachable) {
  std::set<std::string_view> symbols;
  std::set<Phone> phones;
  for (const auto& [symbol, phone] : kEspeakMap) {
    EXPECT_TRUE(symbols.insert(symbol).second) << symbol;
    phones.insert(phone);
  }
  EXPECT_EQ(phones.size(), kPhoneCount);
}

// Every phoneme name espeak-ng 1.51 (en-us) reported while synthesising all 74,288 SUBTLEX-US
// words, numbers, currency, interjections and emoji (spec/phones.md says how they were collected).
TEST(EspeakMap, EverySymbolObservedFromEspeakMaps) {
  const char* observed[] = {"s", "n", "t", "I", "k", "l", "r", "d", "@", "z", "m", "p", "E", "3", "a",
                            "b", "eI", "N", "f", "I#", "i", "oU", "I2", "V", "aI", "0", "t#", "g", "i:",
                            "v", "u:", "S", "@L", "w", ";", "dZ", "h", "a#", "3:", "j", "tS", "A@",
                            "aU", "o@", "O:", "T", "r-", "U", "i@", "aa", "O@", "e@", "_:", "O2", "_",
                            "A:", "OI", "i@3", "U@", "D", "aI3", "Z", "t2", "@-", "aI@", "?", "n-", "x",
                            "O", "A~", "_!", "l#", "e", "_|", "O~", "C", "@2"};
  EXPECT_EQ(std::size(observed), 77u);
  for (const char* symbol : observed) EXPECT_NO_THROW(phone_from_espeak(symbol, "t")) << symbol;
}

TEST(EspeakMap, CitationMnemonicMapsBack) {
  for (const auto& row : kPhoneTable) {
    EXPECT_EQ(phone_from_espeak(espeak_mnemonic(row.phone), "t"), row.phone) << row.arpabet;
  }
}

TEST(EspeakMap, UnknownMnemonicIsAnErrorNamingIt) {
  EXPECT_THROW(phone_from_espeak("@@", "x"), std::invalid_argument);
  try {
    phone_from_espeak("q\x01", "espeak-ng phoneme event");
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "espeak-ng phoneme event: unknown espeak-ng phoneme 'q\\x01'");
  }
}

struct IpaCase { const char* ipa; std::vector<Phone> phones; };
class IpaMap : public testing::TestWithParam<IpaCase> {};
TEST_P(IpaMap, SpellsPhones) { EXPECT_EQ(phones_from_ipa(GetParam().ipa, "t"), GetParam().phones); }
INSTANTIATE_TEST_SUITE_P(Cases, IpaMap, testing::Values(
    // espeak-ng --ipa output for real words (en-us)
    IpaCase{"ɐ pˈʌp", {Phone::AX, Phone::P, Phone::AH, Phone::P}},
    IpaCase{"tʃˈɜːtʃ", {Phone::CH, Phone::ER, Phone::CH}},
    IpaCase{"pˈɑːɹk", {Phone::P, Phone::AA, Phone::R, Phone::K}},
    IpaCase{"θˈɔːt", {Phone::TH, Phone::AO, Phone::T}},
    IpaCase{"bˈʌʔn̩", {Phone::B, Phone::AH, Phone::T, Phone::N}},
    IpaCase{"fˈaɪɚ", {Phone::F, Phone::AY, Phone::ER}},
    IpaCase{"dʒˈɔɪ", {Phone::JH, Phone::OY}},
    IpaCase{"ðə wˈɜːld", {Phone::DH, Phone::AX, Phone::W, Phone::ER, Phone::L, Phone::D}},
    IpaCase{"", {}}));

TEST(IpaMap, UnknownSymbolNamesByteOffsetAndSymbol) {
  try {
    phones_from_ipa("pˈʌʘp", "lexicon:3");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "lexicon:3: byte 5: unknown IPA symbol 'ʘ'");
  }
  EXPECT_THROW(phones_from_ipa("p\xff", "x"), std::invalid_argument);
  EXPECT_THROW(phones_from_ipa("\xe2\x82", "x"), std::invalid_argument);  // truncated UTF-8
}

TEST(TimitMap, All61TimitLabelsMap) {
  // The 61 labels of the TIMIT phone set (TIMIT docs, phoncode.doc).
  const char* labels[] = {"b", "d", "g", "p", "t", "k", "dx", "q", "jh", "ch", "s", "sh", "z", "zh",
                          "f", "th", "v", "dh", "m", "n", "ng", "em", "en", "eng", "nx", "l", "r",
                          "w", "y", "hh", "hv", "el", "iy", "ih", "eh", "ey", "ae", "aa", "aw",
                          "ay", "ah", "ao", "oy", "ow", "uh", "uw", "ux", "er", "ax", "ix", "axr",
                          "ax-h", "pau", "epi", "h#", "bcl", "dcl", "gcl", "pcl", "tcl", "kcl"};
  EXPECT_EQ(std::size(labels), 61u);
  for (const char* label : labels) EXPECT_NO_THROW(phone_from_timit(label, "t")) << label;
}

TEST(TimitMap, ClosuresAreMarkedAndFoldToTheirStop) {
  EXPECT_EQ(phone_from_timit("bcl", "t"), (TimitPhone{Phone::B, true}));
  EXPECT_EQ(phone_from_timit("KCL", "t"), (TimitPhone{Phone::K, true}));
  EXPECT_EQ(phone_from_timit("k", "t"), (TimitPhone{Phone::K, false}));
  EXPECT_EQ(phone_from_timit("h#", "t"), (TimitPhone{Phone::SIL, false}));
}

TEST(TimitMap, UnknownLabelIsAnErrorNamingIt) {
  try {
    phone_from_timit("iy1", "si1027.phn:4");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "si1027.phn:4: unknown TIMIT label 'iy1'");
  }
}

}  // namespace
}  // namespace fapcast
