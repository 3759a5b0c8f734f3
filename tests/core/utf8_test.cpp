#include "fapcast/core/utf8.hpp"

#include <gtest/gtest.h>

#include <string>

namespace fapcast {
namespace {

TEST(Utf8, DecodesOneCodePointOfEachLength) {
  const std::string text = "a\u00e9\u20ac\U0001F600";
  std::size_t at = 0;
  for (const auto& [value, bytes] : {std::pair{U'a', 1u}, {U'\u00e9', 2u}, {U'\u20ac', 3u}, {U'\U0001F600', 4u}}) {
    const Utf8CodePoint c = decode_utf8_at(text, at);
    ASSERT_FALSE(c.error);
    EXPECT_EQ(c.value, value);
    EXPECT_EQ(c.bytes, bytes);
    at += c.bytes;
  }
  EXPECT_EQ(at, text.size());
}

TEST(Utf8, NamesWhatIsWrong) {
  const auto error_of = [](std::string_view bytes) { return decode_utf8_at(bytes, 0).error; };
  EXPECT_EQ(error_of("\x80"), Utf8Error::kBadLead);             // a continuation byte first
  EXPECT_EQ(error_of("\xF8\x80\x80\x80\x80"), Utf8Error::kBadLead);
  EXPECT_EQ(error_of("\xE2\x82"), Utf8Error::kTruncated);
  EXPECT_EQ(error_of("\xE2\x28\xAC"), Utf8Error::kBadContinuation);
  EXPECT_EQ(error_of("\xC0\xAF"), Utf8Error::kOverlong);        // '/' in two bytes
  EXPECT_EQ(error_of("\xED\xA0\x80"), Utf8Error::kNotScalar);   // a surrogate
  EXPECT_EQ(error_of("\xF4\x90\x80\x80"), Utf8Error::kNotScalar);  // above U+10FFFF
  EXPECT_STREQ(utf8_error_text(Utf8Error::kOverlong), "overlong encoding");
  EXPECT_EQ(utf8_sequence_length('\xE2'), 3u);
  EXPECT_EQ(utf8_sequence_length('\x80'), 0u);
}

}  // namespace
}  // namespace fapcast
