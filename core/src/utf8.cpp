#include "fapcast/core/utf8.hpp"

namespace fapcast {

const char* utf8_error_text(Utf8Error error) {
  switch (error) {
    case Utf8Error::kBadLead: return "bad lead byte";
    case Utf8Error::kTruncated: return "truncated sequence";
    case Utf8Error::kBadContinuation: return "bad continuation byte";
    case Utf8Error::kOverlong: return "overlong encoding";
    case Utf8Error::kNotScalar: return "not a scalar value";
  }
  return "invalid UTF-8";
}

std::size_t utf8_sequence_length(char lead) {
  const auto b = static_cast<unsigned char>(lead);
  return b < 0x80 ? 1 : (b & 0xE0) == 0xC0 ? 2 : (b & 0xF0) == 0xE0 ? 3 : (b & 0xF8) == 0xF0 ? 4 : 0;
}

Utf8CodePoint decode_utf8_at(std::string_view text, std::size_t at) {
  const auto fail = [](Utf8Error e) { return Utf8CodePoint{0, 0, e}; };
  const std::size_t n = utf8_sequence_length(text[at]);
  if (n == 0) return fail(Utf8Error::kBadLead);
  if (at + n > text.size()) return fail(Utf8Error::kTruncated);
  const auto lead = static_cast<unsigned char>(text[at]);
  char32_t c = n == 1 ? lead : lead & (0x7F >> n);
  for (std::size_t k = 1; k < n; ++k) {
    const auto next = static_cast<unsigned char>(text[at + k]);
    if ((next & 0xC0) != 0x80) return fail(Utf8Error::kBadContinuation);
    c = (c << 6) | (next & 0x3F);
  }
  static constexpr char32_t kMinForLength[] = {0, 0, 0x80, 0x800, 0x10000};
  if (c < kMinForLength[n]) return fail(Utf8Error::kOverlong);
  if (c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return fail(Utf8Error::kNotScalar);
  return {c, n, std::nullopt};
}

}  // namespace fapcast
