#include "fapcast/transport/srtp_key.hpp"

#include "fapcast/core/file_io.hpp"
#include "fapcast/core/input_error.hpp"

#include <algorithm>
#include <random>

namespace fapcast {
namespace {
constexpr std::string_view kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
constexpr std::string_view kInline = "inline:";

int sextet(char c) {
  const auto at = kAlphabet.find(c);
  return at == std::string_view::npos ? -1 : static_cast<int>(at);
}
}  // namespace

SrtpMasterKey parse_srtp_key(std::string_view text, const std::string& source) {
  const auto fail = [&](std::size_t offset, const char* rule, const std::string& detail) {
    return InputError({source, std::nullopt, offset}, rule, detail);
  };
  std::size_t begin = 0, end = text.size();
  while (begin < end && (text[begin] == ' ' || text[begin] == '\t')) ++begin;
  while (end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
  if (const auto at = text.find(kInline, begin); at != std::string_view::npos && at != begin)
    throw fail(begin, "srtp-key-base64",
               std::to_string(at - begin) +
                   " bytes before 'inline:' (an SDP a=crypto line?): the file holds the key alone, optionally after inline:");
  if (text.substr(begin, kInline.size()) == kInline) begin += kInline.size();
  std::vector<std::uint8_t> bytes;
  std::uint32_t bits = 0;
  int held = 0;
  std::size_t padding = 0;
  for (std::size_t i = begin; i < end; ++i) {
    const char c = text[i];
    if (c == '=') {
      ++padding;
      continue;
    }
    const int v = sextet(c);
    if (v < 0 || padding > 0)
      throw fail(i, "srtp-key-base64",
                 padding > 0 ? std::string("data after '=' padding")
                             : "character " + std::to_string(static_cast<unsigned char>(c)) +
                                   " is not base64 (A-Z a-z 0-9 + /)");
    bits = (bits << 6) | static_cast<std::uint32_t>(v);
    held += 6;
    if (held >= 8) {
      held -= 8;
      bytes.push_back(static_cast<std::uint8_t>(bits >> held));
    }
  }
  const std::size_t chars = end - begin;
  if (chars % 4 != 0 || padding > 2)
    throw fail(end, "srtp-key-base64", std::to_string(chars) + " characters: base64 comes in groups of 4");
  if (bytes.size() != kSrtpMasterKeyBytes)
    throw fail(begin, "srtp-key-length",
               std::to_string(bytes.size()) + " bytes; AES_CM_128_HMAC_SHA1_80 takes " +
                   std::to_string(kSrtpMasterKeyBytes) + " (16 of key, 14 of salt: 40 base64 characters)");
  if (std::all_of(bytes.begin(), bytes.end(), [&](std::uint8_t b) { return b == bytes[0]; }))
    throw fail(begin, "srtp-key-weak", "every byte is the same: a placeholder, not a key");
  SrtpMasterKey key;
  std::copy(bytes.begin(), bytes.end(), key.bytes.begin());
  return key;
}

SrtpMasterKey read_srtp_key_file(const std::filesystem::path& path) {
  std::string text = read_file(path, 4096);
  if (!text.empty() && text.back() == '\n') text.pop_back();
  if (!text.empty() && text.back() == '\r') text.pop_back();
  if (text.find('\n') != std::string::npos)
    throw InputError::in_file(path.string(), 2, "srtp-key-file", "the key file holds one line: the base64 key");
  return parse_srtp_key(text, path.string());
}

std::string srtp_key_text(const SrtpMasterKey& key) {
  std::string out;
  for (std::size_t i = 0; i < key.bytes.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t{key.bytes[i]} << 16) | (std::uint32_t{key.bytes[i + 1]} << 8) |
                            key.bytes[i + 2];  // 30 bytes: whole groups of 3
    for (int s = 18; s >= 0; s -= 6) out.push_back(kAlphabet[(n >> s) & 63]);
  }
  return out;
}

SrtpMasterKey random_srtp_key() {
  std::random_device rd;
  SrtpMasterKey key;
  for (auto& b : key.bytes) b = static_cast<std::uint8_t>(rd());
  return key;
}

}  // namespace fapcast
