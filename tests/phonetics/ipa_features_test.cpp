// Phone classes from IPA features: the chart's features decide, diacritics are skipped, the
// classes agree with the hand-made IPA map wherever that has a one-letter row, and unknown
// symbols are errors naming symbol, code point, phoneme and source.
#include "fapcast/phonetics/ipa_features.hpp"
#include "fapcast/phonetics/phone_map.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace fapcast {
namespace {

std::size_t code_points(std::string_view s) {
  std::size_t n = 0;
  for (const char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

struct Case { std::string ipa; std::optional<Phone> phone; };
class IpaFeatures : public testing::TestWithParam<Case> {};
TEST_P(IpaFeatures, GivesThePhoneOfItsFeatures) {
  EXPECT_EQ(phone_from_ipa_features(GetParam().ipa, "t"), GetParam().phone) << GetParam().ipa;
}
INSTANTIATE_TEST_SUITE_P(Cases, IpaFeatures, testing::Values(
    // Russian, Arabic, Hindi, Korean phonemes as espeak-ng's IPA events name them
    Case{"oː", Phone::OW}, Case{"ɐ", Phone::AX}, Case{"ɨ", Phone::IH}, Case{"tʲ", Phone::T},
    Case{"ʂ", Phone::SH}, Case{"ɕː", Phone::SH}, Case{"ħ", Phone::HH}, Case{"ʕ", Phone::HH},
    Case{"s̪", Phone::S}, Case{"ʈʰ", Phone::T}, Case{"ɖ", Phone::D}, Case{"ɡʰ", Phone::G},
    Case{"ɳ", Phone::N}, Case{"ɯ", Phone::IH}, Case{"tɕh", Phone::CH}, Case{"ʌ", Phone::AH},
    // affricates: postalveolar-like fricative after a stop; other fricatives keep the stop
    Case{"tʃ", Phone::CH}, Case{"t͡ʃ", Phone::CH}, Case{"dʒ", Phone::JH}, Case{"ʈ͡ʂ", Phone::CH},
    Case{"ts", Phone::T}, Case{"d̻͡z̪", Phone::D}, Case{"ʦ", Phone::T}, Case{"ʤ", Phone::JH},
    // diphthongs: nucleus and close glide; rising sequences take the open nucleus
    Case{"aɪ", Phone::AY}, Case{"aʊ", Phone::AW}, Case{"eɪ", Phone::EY}, Case{"oʊ", Phone::OW},
    Case{"ɔɪ", Phone::OY}, Case{"əʊ", Phone::OW}, Case{"iɛ", Phone::EH}, Case{"iou", Phone::OW},
    Case{"ja", Phone::AE}, Case{"əl", Phone::AX}, Case{"ui", Phone::UW},
    // front rounded vowels, uvulars, taps, trills, approximants
    Case{"y", Phone::UW}, Case{"ø", Phone::ER}, Case{"œ̃", Phone::ER}, Case{"ʁ", Phone::G},
    Case{"χ", Phone::K}, Case{"ɾ", Phone::T}, Case{"r", Phone::R}, Case{"ɹ", Phone::R},
    Case{"ʋ", Phone::V}, Case{"β", Phone::V}, Case{"ɥ", Phone::W}, Case{"ʎ", Phone::L},
    // espeak-ng's ASCII fallbacks for phonemes without IPA
    Case{"tS", Phone::CH}, Case{"dZ", Phone::JH}, Case{"N", Phone::NG}, Case{"?a", Phone::AE},
    Case{"n^", Phone::N}, Case{"l#", Phone::L}, Case{"t`", Phone::T},
    // other languages' mnemonics when en-us switches by script (ru o: R2, hi J H)
    Case{"o:", Phone::OW}, Case{"R2", Phone::R}, Case{"J", Phone::G}, Case{"H", Phone::HH},
    Case{"(en-us-n", std::nullopt},
    // pauses; events with nothing to say
    Case{"", Phone::SIL}, Case{"_", Phone::SIL}, Case{"_:", Phone::SIL},
    Case{"(en)", std::nullopt}, Case{"ʲ", std::nullopt}, Case{"ː", std::nullopt}));

TEST(IpaFeatures, AgreesWithTheIpaMapOnEveryOneLetterRow) {
  std::size_t checked = 0;
  for (const auto& [symbol, phone] : kIpaMap) {
    if (code_points(symbol) != 1) continue;
    EXPECT_EQ(phone_from_ipa_features(symbol, "t"), phone) << symbol;
    ++checked;
  }
  EXPECT_GT(checked, 40u);
}

TEST(IpaFeatures, EveryLetterOfTheChartHasFeatures) {
  for (const char32_t c : {U'p', U'\u0288', U'\u0262', U'\u0294', U'\u0271', U'\u0274', U'\u0299',
                           U'\u2C71', U'\u0278', U'\u0267', U'\u026E', U'\u0270', U'\u029F',
                           U'\u0276', U'\u0264', U'\u1D7B'}) {
    EXPECT_TRUE(ipa_segment(c).has_value()) << static_cast<unsigned>(c);
  }
  EXPECT_FALSE(ipa_segment(U'\u01C3').has_value());  // a click
}

TEST(IpaFeatures, UnknownSymbolNamesSymbolCodePointPhonemeAndSource) {
  try {
    phone_from_ipa_features("ǃa", "espeak-ng phoneme event (language zu)");
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "espeak-ng phoneme event (language zu): unknown IPA symbol 'ǃ' (U+01C3) in phoneme 'ǃa'");
  }
  try {
    phone_from_ipa_features("a\x01", "s");
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "s: unknown IPA symbol '\\x01' (U+0001) in phoneme 'a\\x01'");
  }
  try {
    phone_from_ipa_features("a\xc3", "s");
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "s: invalid UTF-8 at byte 1 in phoneme 'a\xc3'");
  }
}

}  // namespace
}  // namespace fapcast
