#include "fapcast/core/input_error.hpp"

#include <string_view>
#include <utility>

namespace fapcast {
namespace {
// The length of the well-formed UTF-8 sequence at text[i] (RFC 3629: no overlongs, no
// surrogates, at most U+10FFFF), or 0.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = b(i);
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xbf;
  if (c >= 0xc2 && c <= 0xdf) n = 2;
  else if (c >= 0xe0 && c <= 0xef) n = 3, lo = c == 0xe0 ? 0xa0 : 0x80, hi = c == 0xed ? 0x9f : 0xbf;
  else if (c >= 0xf0 && c <= 0xf4) n = 4, lo = c == 0xf0 ? 0x90 : 0x80, hi = c == 0xf4 ? 0x8f : 0xbf;
  else return 0;
  if (i + n > text.size() || b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (b(i + k) < 0x80 || b(i + k) > 0xbf) return 0;
  return n;
}

std::string format(const InputLocation& at, const std::string& rule, const std::string& detail) {
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on long operator+ chains at -O2.
  std::string s = at.source.empty() ? std::string("<memory>") : at.source;
  if (at.line) s.append(":").append(std::to_string(*at.line));
  if (at.offset) s.append(": byte ").append(std::to_string(*at.offset));
  s.append(": ").append(rule).append(": ").append(escape_for_message(detail));
  return s;
}
}  // namespace

std::string escape_for_message(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out.push_back(static_cast<char>(c));
      ++i;
    } else if (const std::size_t n = c >= 0x80 ? utf8_length(text, i) : 0; n > 0) {
      out.append(text.substr(i, n));
      i += n;
    } else {
      out.append("\\x").push_back(kHex[c >> 4]);
      out.push_back(kHex[c & 15]);
      ++i;
    }
  }
  return out;
}

InputError::InputError(InputLocation where, std::string rule, const std::string& detail)
    : std::runtime_error(format(where, rule, detail)), where_(std::move(where)),
      rule_(std::move(rule)) {}

InputError InputError::in_file(std::string file, std::uint64_t line, std::string rule, const std::string& detail) {
  return InputError({std::move(file), line == 0 ? std::nullopt : std::optional<std::uint64_t>(line), std::nullopt},
                    std::move(rule), detail);
}

}  // namespace fapcast
