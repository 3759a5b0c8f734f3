#pragma once
// Reading UTF-8 one code point at a time: the one decoder behind every text rule (the front-end's
// input check, transcripts, espeak-ng's IPA phoneme names, decode_text).
#include <cstddef>
#include <optional>
#include <string_view>

namespace fapcast {

// Why the bytes at an offset are not one UTF-8 code point.
enum class Utf8Error { kBadLead, kTruncated, kBadContinuation, kOverlong, kNotScalar };

// "bad lead byte", "truncated sequence", "bad continuation byte", "overlong encoding",
// "not a scalar value".
const char* utf8_error_text(Utf8Error error);

// The length of the sequence a lead byte starts (1-4), or 0 for a continuation byte or a byte
// no sequence starts with (F8-FF).
std::size_t utf8_sequence_length(char lead);

struct Utf8CodePoint {
  char32_t value = 0;
  std::size_t bytes = 0;           // its length; 0 when `error` is set
  std::optional<Utf8Error> error;  // why text[at] does not start a code point
};

// The code point that starts at text[at] (at < text.size()), checked in this order: lead byte,
// length, continuation bytes, shortest form, scalar value (no surrogates, at most U+10FFFF).
Utf8CodePoint decode_utf8_at(std::string_view text, std::size_t at);

}  // namespace fapcast
