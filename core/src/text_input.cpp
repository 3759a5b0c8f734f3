#include "fapcast/core/text_input.hpp"

#include "fapcast/core/utf8.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace fapcast {
namespace {

void append_utf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// 1-based line of byte `offset` in UTF-8 `text`, for error messages.
std::uint64_t line_of(std::string_view text, std::size_t offset) {
  std::uint64_t line = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

// The offset of the first byte that breaks UTF-8 (overlongs, surrogates, > U+10FFFF, NUL), or npos.
std::size_t first_invalid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    if (s[i] == 0) return i;
    const Utf8CodePoint c = decode_utf8_at(s, i);
    if (c.error) return i;
    i += c.bytes;
  }
  return std::string_view::npos;
}

std::string decode_utf16(std::string_view bytes, bool big_endian, const std::string& source,
                         const std::string& rule) {
  if (bytes.size() % 2 != 0) {
    throw InputError({source, std::nullopt, bytes.size() + 1}, rule,
                     "UTF-16 text has an odd number of bytes");
  }
  auto unit = [&](std::size_t i) {
    const auto a = static_cast<unsigned char>(bytes[i]);
    const auto b = static_cast<unsigned char>(bytes[i + 1]);
    return static_cast<char32_t>(big_endian ? (a << 8 | b) : (b << 8 | a));
  };
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 2) {
    char32_t c = unit(i);
    const std::uint64_t at = i + 2;  // offset in the file, after the 2-byte BOM
    if (c >= 0xD800 && c <= 0xDBFF) {
      if (i + 4 > bytes.size() || unit(i + 2) < 0xDC00 || unit(i + 2) > 0xDFFF) {
        throw InputError({source, std::nullopt, at}, rule, "UTF-16 high surrogate without a low one");
      }
      c = 0x10000 + ((c - 0xD800) << 10) + (unit(i + 2) - 0xDC00);
      i += 2;
    } else if (c >= 0xDC00 && c <= 0xDFFF) {
      throw InputError({source, std::nullopt, at}, rule, "UTF-16 low surrogate without a high one");
    } else if (c == 0) {
      throw InputError({source, std::nullopt, at}, rule, "NUL character in text");
    }
    append_utf8(out, c);
  }
  return out;
}

}  // namespace

void fail_at_line(const std::string& source, std::uint64_t line, const std::string& rule,
                  const std::string& detail) {
  throw InputError({source, line, std::nullopt}, rule, detail);
}

std::string decode_text(std::string_view bytes, const std::string& source, std::string_view format) {
  const std::string rule = std::string(format) + "-encoding";
  if (bytes.starts_with("\xFF\xFE")) return decode_utf16(bytes.substr(2), false, source, rule);
  if (bytes.starts_with("\xFE\xFF")) return decode_utf16(bytes.substr(2), true, source, rule);
  const std::size_t bom = bytes.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  const std::string_view text = bytes.substr(bom);
  if (const std::size_t bad = first_invalid_utf8(text); bad != std::string_view::npos) {
    throw InputError({source, line_of(text, bad), std::nullopt}, rule,
                     text[bad] == '\0' ? "NUL byte (UTF-16 without a byte-order mark?)"
                                       : "invalid UTF-8 at byte " + std::to_string(bad + bom));
  }
  return std::string(text);
}

std::vector<TextLine> split_lines(std::string_view text) {
  std::vector<TextLine> lines;
  std::uint64_t number = 1;
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n' && text[i] != '\r') continue;
    lines.push_back({text.substr(start, i - start), number++});
    if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    start = i + 1;
  }
  if (start < text.size()) lines.push_back({text.substr(start), number});
  return lines;
}

std::vector<std::string_view> split_fields(std::string_view text, char separator) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == separator) {
      fields.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  }
  return fields;
}

std::vector<std::string_view> split_whitespace(std::string_view text) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
    if (i > start) fields.push_back(text.substr(start, i - start));
  }
  return fields;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

bool parse_finite(std::string_view field, double& value) {
  if (field.starts_with('+')) {
    field.remove_prefix(1);
    if (field.starts_with('-')) return false;
  }
  if (field.empty()) return false;
  double v = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
  if (ec != std::errc{} || end != field.data() + field.size() || !std::isfinite(v)) return false;
  value = v;
  return true;
}

bool parse_count(std::string_view field, std::int64_t& value) {
  std::int64_t v = 0;
  if (field.empty() || field.front() == '-' || field.front() == '+') return false;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
  if (ec != std::errc{} || end != field.data() + field.size()) return false;
  value = v;
  return true;
}

std::string shortest_decimal(double value) {
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  (void)ec;  // 64 bytes always hold the shortest form of a double
  return std::string(buffer, end);
}

std::string excerpt(std::string_view text) {
  if (text.size() <= 40) return std::string(text);
  return std::string(text.substr(0, 40)) + "...";
}

}  // namespace fapcast
